#pragma once
// The CPU image of shaders/shadow_data.glsl's std140 block: every member an array of vec4 or
// mat4, so std140 adds no padding and the struct's layout is the block's.
#include "engine/render/Frame.h"
#include "math/CascadeFit.h"

#include <glm/glm.hpp>

#include <cstddef>

namespace shadowmap {

// The block's binding point (shadow_data.glsl says the same); the lit pass's lights use 0.
constexpr unsigned kShadowBlockBinding = 1;

struct ShadowBlock {
    glm::mat4 eyePlanes[engine::kMaxLights];
    glm::vec4 params[engine::kMaxLights];
    glm::vec4 pointLight[engine::kMaxLights];
    glm::vec4 pointFar[engine::kMaxLights];  // x: far, y: cube texel bias (a float array would have a 16-byte stride anyway)
    glm::mat4 eyeToWorld;
    glm::mat4 cascadePlanes[engine::kMaxLights * kMaxCascades];  // light slot * 4 + cascade
    glm::vec4 cascadeFar[engine::kMaxLights];                    // far view depth per cascade
    glm::vec4 cascadeBlend[engine::kMaxLights];                  // x: blend fraction, y: first split
};

static_assert(offsetof(ShadowBlock, params) == engine::kMaxLights * 64);
static_assert(offsetof(ShadowBlock, pointLight) == engine::kMaxLights * 80);
static_assert(offsetof(ShadowBlock, pointFar) == engine::kMaxLights * 96);
static_assert(offsetof(ShadowBlock, eyeToWorld) == engine::kMaxLights * 112);
static_assert(offsetof(ShadowBlock, cascadePlanes) == engine::kMaxLights * 112 + 64);
static_assert(offsetof(ShadowBlock, cascadeFar) == engine::kMaxLights * (112 + 64 * kMaxCascades) + 64);
static_assert(offsetof(ShadowBlock, cascadeBlend) == engine::kMaxLights * (128 + 64 * kMaxCascades) + 64);
static_assert(sizeof(ShadowBlock) == engine::kMaxLights * (144 + 64 * kMaxCascades) + 64);

} // namespace shadowmap
