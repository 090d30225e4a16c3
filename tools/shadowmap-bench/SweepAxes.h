#pragma once
// The sweep's optional axes (--light-radii with --angular-diameters, --filter-radii,
// --filter-taps, --normal-offsets; BenchOptions.h) and how one setting is written into a
// light: the one place that knows which axis applies to which row and which key to which
// type of light.
#include "BenchOptions.h"
#include "BenchRow.h"

#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace shadowmap_bench {

// Every setting of `settings` times the axes that apply to it, in this order: each light size
// step, each filter radius (pcf only), each tap count (pcss, and pcf with a filter radius
// > 0), each normal offset. An axis not given, or not applying, leaves the setting as it is
// (the field unset), so with no axis given the list comes back unchanged.
std::vector<ShadowSetting> expandAxes(const std::vector<ShadowSetting>& settings, const BenchOptions& options);

// The keys of a light's extras.shadow that `setting` writes for a light of `type`: variant,
// resolution, depth_format, filter, and each optional field that is set; of the size step
// only the key of the light's type (light_radius for spot and point, angular_diameter for
// directional), since the plugin refuses the other.
nlohmann::json lightShadow(const ShadowSetting& setting, engine::Light::Type type);

} // namespace shadowmap_bench
