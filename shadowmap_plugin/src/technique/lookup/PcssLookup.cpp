#include "technique/lookup/PcssLookup.h"

namespace shadowmap {

namespace shaders {
extern const char pcss_glsl[];
} // namespace shaders

const char* PcssLookup::glsl() const { return shaders::pcss_glsl; }

} // namespace shadowmap
