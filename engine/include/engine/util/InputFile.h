#pragma once
// A whole file read into memory, for the text formats the engine and its tools parse
// (configs, scenes, scripts, results). Throws InputError "path: cannot read <what>" when the
// file cannot be opened or read, so every caller reports the same way.
#include <filesystem>
#include <string>
#include <string_view>

namespace engine {

// `what` names the file's role for the message, e.g. "the engine config".
std::string readWholeFile(const std::filesystem::path& path, std::string_view what);

} // namespace engine
