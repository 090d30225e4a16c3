#pragma once
// What each light's shadow needs this frame, decided on the CPU from the scene and the
// camera alone (no GL): whether it gets a map, its projection's views (frusta, cube faces,
// cascades and their count), and whether the map it last rendered is still right. The
// plugin turns the plan into textures and graph passes; unit tests check it without a GL
// context.
#include "technique/LightState.h"
#include "technique/MapProjection.h"

namespace shadowmap {

// Receivers the camera can see (only they need shadows this frame) and every caster.
ShadowBounds frameBounds(const engine::Scene& scene, const engine::FrameCamera& camera);
// Every receiver and caster of the scene, seen or not: what a stable cascade anchors to.
engine::Aabb sceneBounds(const engine::Scene& scene);
// The inputs of planLight for this frame.
PlanContext planContext(const engine::Scene& scene, const engine::FrameCamera& camera);

// Fills light.frame for this frame (reset first); true when the light gets a map (its kind
// is then set). False with frame.skipReason saying why: variant none, a light that emits
// nothing, a degenerate light, no visible receiver in its frustum, or no texture unit left
// (`textureUnit`: the unit its map would use, `maxTextureUnits`: the GL's count).
// Warnings for people go to frame.warnings.
bool planLight(LightState& light, const PlanContext& context, int textureUnit, int maxTextureUnits);

// With the map's texture in place (a new texture holds nothing: rendered keys 0): sets the
// map's key and whether it (or each cascade layer) is still right. cacheMaps false: never.
void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration, bool cacheMaps);

} // namespace shadowmap
