#pragma once
// The inputs a shadow map depends on, hashed: if a light's key is unchanged since its map
// was last rendered, the map is still right and its depth passes are skipped.
// Covered: the scene (a generation bumped on every prepareScene: geometry, materials and
// closedness only change there), the light's settings and map kind, the fitted view(s)
// (so a moved light, a moved camera that changes a directional fit, or a changed near/far
// all miss), and every caster inside the frustum: which mesh, its world transform.
// Casters outside the frustum do not draw into the map, so moving them keeps the hit.
#include "technique/LightState.h"

#include "engine/scene/Scene.h"

#include <cstdint>

namespace shadowmap {

std::uint64_t mapCacheKey(const LightState& light, const engine::Scene& scene,
                          std::uint64_t sceneGeneration);

// The key of one layer of a cascaded directional light's map: the same inputs, over that
// cascade's view and the casters inside it only. A stable cascade moves in whole texels,
// so while the camera walks less than a texel of it (or along its light's axis) its key
// holds and its layer is kept while nearer cascades re-render.
std::uint64_t cascadeCacheKey(const LightState& light, int cascade, const engine::Scene& scene,
                              std::uint64_t sceneGeneration);

// A key with the depth settings that change a map without changing its view-projection:
// reversed Z's depth state and the slope-offset clamp.
std::uint64_t withDepthSettings(std::uint64_t key, const ShadowSettings& settings);

} // namespace shadowmap
