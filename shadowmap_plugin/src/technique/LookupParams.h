#pragma once
// The uniform block's per-light lookup settings (shaders/shadow_data.glsl, lookupParams):
// filter_radius, pcss's blocker-search taps, filter_taps and normal_offset, as the lookups
// read them whatever the light's map.
#include "shadowmap/ShadowSettings.h"

#include <glm/glm.hpp>

namespace shadowmap {

glm::vec4 lookupParams(const ShadowSettings& settings);

} // namespace shadowmap
