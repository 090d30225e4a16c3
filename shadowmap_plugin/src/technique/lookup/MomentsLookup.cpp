#include "technique/lookup/MomentsLookup.h"

namespace shadowmap {

namespace shaders {
extern const char vsm_glsl[];
extern const char evsm_glsl[];
} // namespace shaders

const char* MomentsLookup::glsl() const { return filter_ == Filter::Evsm ? shaders::evsm_glsl : shaders::vsm_glsl; }

} // namespace shadowmap
