#pragma once
// Runs gnuplot on a script in its own folder (so the script's relative output path lands
// next to it), writing the picture to a temporary name that the caller renames into place.
#include <filesystem>
#include <string>

namespace shadowmap_bench {

// Returns an empty string on success, else one line saying why (gnuplot missing, or its
// exit status); gnuplot's own messages go to stderr.
std::string runGnuplot(const std::filesystem::path& script, const std::string& outputName);

} // namespace shadowmap_bench
