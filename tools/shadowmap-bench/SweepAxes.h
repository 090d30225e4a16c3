#pragma once
// The sweep's optional axes (--light-radii with --angular-diameters, --filter-radii,
// --filter-taps, --bleed-reductions, --normal-offsets, and the directional lights' --projections, --cascades,
// --stables; BenchOptions.h) and how one setting is written into a
// light: the one place that knows which axis applies to which row and which key to which
// type of light.
#include "BenchOptions.h"
#include "BenchRow.h"

#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace shadowmap_bench {

// Every setting of `settings` times the axes that apply to it, in this order: each light size
// step, each filter radius (pcf, vsm, evsm), each tap count (pcss, and pcf with a filter
// radius > 0), each bleed reduction (vsm, evsm), each normal offset, each projection, each cascade count, each stable value (rows
// whose projection is not lispsm: a warp is never stable). A volume setting (no map) takes
// the size steps only. An axis not given, or not applying, leaves the setting as it is
// (the field unset), so with no axis given the list comes back unchanged.
std::vector<ShadowSetting> expandAxes(const std::vector<ShadowSetting>& settings, const BenchOptions& options);

// The keys of a light's extras.shadow that `setting` writes for a light of `type`: variant,
// resolution, depth_format, filter (a map's only: a volume setting writes none of them),
// and each optional field that is set (filter_radius,
// filter_taps, bleed_reduction, normal_offset); of the size step
// only the key of the light's type (light_radius for spot and point, angular_diameter for
// directional), since the plugin refuses the other; projection, cascades and stable for a
// directional light only (a spot or point light refuses projection "lispsm").
nlohmann::json lightShadow(const ShadowSetting& setting, engine::Light::Type type);

// Sets each setting's directionalRepeat: whether an earlier one of `settings` differs from it
// only in projection, cascades and stable (which a spot or point light never gets). Run on a
// scene's accepted settings before sharding, so every shard agrees on which job writes a spot
// or point light's row.
void markDirectionalRepeats(std::vector<ShadowSetting>& settings);

// Whether a job under `setting` writes a row for a light of `type`: a directional light's
// always, a spot or point light's only where the setting is no directional repeat.
bool writesRowFor(const ShadowSetting& setting, engine::Light::Type type);

// The setting as a light of `type` got it (its row's): without projection, cascades and
// stable for a spot or point light.
ShadowSetting rowSetting(const ShadowSetting& setting, engine::Light::Type type);

} // namespace shadowmap_bench
