#pragma once
// The CPU image of shaders/shadow_data.glsl's std140 block: every member an array of vec4 or
// mat4, so std140 adds no padding and the struct's layout is the block's.
#include "engine/render/Frame.h"
#include "math/CascadeFit.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>

namespace shadowmap {

// The block's binding point: the first a visibility hook may use (the lit pass's lights
// come before it).
constexpr unsigned kShadowBlockBinding = engine::kFirstPluginUniformBinding;

struct ShadowBlock {
    glm::mat4 eyePlanes[engine::kMaxLights];
    glm::vec4 params[engine::kMaxLights];
    glm::vec4 lightInEye[engine::kMaxLights];  // xyz: position (spot, point) or toward the light (directional); w: 1, 0
    glm::vec4 pointFar[engine::kMaxLights];  // x: far, y: cube texel bias, z: near (a float array would have a 16-byte stride anyway)
    glm::mat4 eyeToWorld;
    glm::mat4 cascadePlanes[engine::kMaxLights * kMaxCascades];  // light slot * kMaxCascades + cascade
    glm::vec4 cascadeFar[engine::kMaxLights];                    // far view depth per cascade
    glm::vec4 cascadeBlend[engine::kMaxLights];  // x: blend fraction, y: first split, z, w: fade end, start
    // Soft shadows (technique/SoftShadowLayers.h): per light and layer (2D map and cube: 0)
    // and per light.
    glm::vec4 softLayers[engine::kMaxLights * kMaxCascades];
    // What the lookup reads beyond the map (technique/LookupParams.h): filter and normal
    // offset per light; a texel's width per light (2D map, cube) or per cascade.
    glm::vec4 lookupParams[engine::kMaxLights];
    glm::vec4 texelWidths[engine::kMaxLights];
};

// cascadeFar holds a light's cascades' far depths in one vec4 (visibility.glsl compares it
// with the pixel's depth at once).
static_assert(kMaxCascades <= 4);
static_assert(offsetof(ShadowBlock, params) == engine::kMaxLights * 64);
static_assert(offsetof(ShadowBlock, lightInEye) == engine::kMaxLights * 80);
static_assert(offsetof(ShadowBlock, pointFar) == engine::kMaxLights * 96);
static_assert(offsetof(ShadowBlock, eyeToWorld) == engine::kMaxLights * 112);
static_assert(offsetof(ShadowBlock, cascadePlanes) == engine::kMaxLights * 112 + 64);
static_assert(offsetof(ShadowBlock, cascadeFar) == engine::kMaxLights * (112 + 64 * kMaxCascades) + 64);
static_assert(offsetof(ShadowBlock, cascadeBlend) == engine::kMaxLights * (128 + 64 * kMaxCascades) + 64);
static_assert(offsetof(ShadowBlock, softLayers) == engine::kMaxLights * (144 + 64 * kMaxCascades) + 64);
static_assert(offsetof(ShadowBlock, lookupParams) == engine::kMaxLights * (144 + 80 * kMaxCascades) + 64);
static_assert(offsetof(ShadowBlock, texelWidths) == engine::kMaxLights * (160 + 80 * kMaxCascades) + 64);
static_assert(sizeof(ShadowBlock) == engine::kMaxLights * (176 + 80 * kMaxCascades) + 64);
// Within the 16 KiB every GL 4.5 implementation must allow a uniform block
// (GL_MAX_UNIFORM_BLOCK_SIZE's minimum).
static_assert(sizeof(ShadowBlock) <= 16384);

// The constants shadow_data.glsl and visibility.glsl take from here, as #defines to put
// before them (MAX_LIGHTS comes from the lit pass's own header).
inline std::string shadowBlockGlslDefines() {
    return "#define SHADOW_BLOCK_BINDING " + std::to_string(kShadowBlockBinding) + "\n#define MAX_CASCADES " +
           std::to_string(kMaxCascades) + "\n";
}

} // namespace shadowmap
