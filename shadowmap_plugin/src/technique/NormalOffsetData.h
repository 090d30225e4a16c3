#pragma once
// The uniform block's entries the normal offset reads (shaders/map_shapes.glsl,
// normalOffset; shaders/shadow_data.glsl says what each component holds): how wide a texel
// of the map is at the receiver, and where the light is, both in eye space. Each
// projection packs its map's.
#include "math/LightFrustum.h"

#include <engine/scene/Scene.h>

#include <glm/glm.hpp>

namespace shadowmap {

// A texel's width in world (and eye) units per unit of q for a 2D map or one cascade
// (texgen.glsl's q: the distance along the light's axis in a perspective view, 1 in an
// orthographic one): map coordinates s = (P[0][0] x / q + 1) / 2, so a texel 1/resolution
// wide in s is 2 q / (P[0][0] resolution) wide in x; the wider of x and y.
// A warped map (LispsmWarp.h, q: the distance along the warp axis) has texels 2 q / (O00
// resolution) wide across the warp: this.
float texelWidthPerDepth(const LightView& view, int resolution);
// ... and q^2 (f - n) / (O11 f n resolution) long along it: this is that width per q^2
// (0 for any other map), so the width at the receiver is max(a q, b q^2) for every 2D map.
float texelWidthPerDepthSquared(const LightView& view, int resolution);

// A cube face is a 90-degree view (P[0][0] = 1): a texel per unit of the major-axis distance.
inline float cubeTexelWidthPerDepth(int resolution) { return 2.0f / static_cast<float>(resolution); }

// Where the light of `view` is for eye space `worldToEye` (V^-1): a spot light's position
// (w 1), or the direction toward a directional light (w 0).
glm::vec4 lightInEye(const LightView& view, engine::Light::Type type, const glm::dmat4& worldToEye);

} // namespace shadowmap
