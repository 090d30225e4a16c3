#include "engine/util/InputFile.h"

#include "engine/util/Error.h"

#include <fstream>
#include <sstream>

namespace engine {

std::string readWholeFile(const std::filesystem::path& path, std::string_view what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(path.string(), "", "cannot read " + std::string(what));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return std::move(bytes).str();
}

} // namespace engine
