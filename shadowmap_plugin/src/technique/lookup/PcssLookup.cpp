#include "technique/lookup/PcssLookup.h"

#include <string>

namespace shadowmap {

namespace shaders {
extern const char pcss_glsl[];
} // namespace shaders

const char* PcssLookup::glsl() const {
    static const std::string code =
        "const float kPcssMaxRadiusTexels = " + std::to_string(kMaxRadiusTexels) + ".0;\n" + shaders::pcss_glsl;
    return code.c_str();
}

} // namespace shadowmap
