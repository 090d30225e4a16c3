#include "technique/lookup/WidePcfLookup.h"

namespace shadowmap {

namespace shaders {
extern const char widePcf_glsl[];
} // namespace shaders

const char* WidePcfLookup::glsl() const { return shaders::widePcf_glsl; }

} // namespace shadowmap
