#pragma once
// Each light instance's settings, resolved once per scene: the plugin's defaults, then the
// light's glTF extras.shadow, then KHR_lights_shadows castShadows false, then the command
// line's per-light settings; checked against the GL's limits. Bad input is an error naming
// the scene, the light and the key before any frame is drawn.
#include "plugin/LightShadow.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace shadowmap {

using LightOptions = std::map<std::string, nlohmann::json>;  // light name -> {key: value}

// One LightShadow per lit-pass light slot (at most engine::kMaxClusteredLights). `warn` hears what is
// set but not used.
std::vector<LightShadow> resolveLights(const engine::Scene& scene, const ShadowSettings& defaults,
                                       const LightOptions& options, int maxTextureSize,
                                       const std::function<void(const LightState&, const std::string&)>& warn);

// Per Scene::meshes: closed and meant to cast from its outside only. The backface variant
// may cull front faces only of such casters: a double-sided material means the surface is
// seen (and casts) from both sides, and an alpha-tested one has holes whatever its geometry
// (light passes through the front face and must be stopped by the back face's opaque texels).
std::vector<bool> closedCasterMeshes(const engine::Scene& scene);

} // namespace shadowmap
