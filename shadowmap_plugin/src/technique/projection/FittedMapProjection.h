#pragma once
// One 2D map fitted around what a spot or directional light must hold (LightFrustum.h):
// a perspective frustum for a spot light, a box for a directional one. Looked up through
// eye-linear texgen planes Ee = S * P_light * L^-1 * V (Texgen.h).
#include "technique/MapProjection.h"

namespace shadowmap {

class FittedMapProjection final : public MapProjection {
public:
    MapKind kind() const override { return MapKind::Map2D; }
    const char* name() const override { return "2d"; }
    ProjectionFit fit(LightState& light, const PlanContext& context, const FrustumFitOptions& options) const override;
    MapShape shape(const LightState&) const override { return {}; }
    void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                     bool cacheMaps) const override;
    std::vector<MapLayer> layers(const LightState& light) const override;
    const LightView& finestView(const LightState& light) const override { return light.frame.view; }
    bool packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                    HookGlsl::Lookup& lookup) const override;
    void addStats(const LightState& light, nlohmann::json& stats) const override;
    void describe(const LightState& light, engine::ShadowView& view) const override;
};

} // namespace shadowmap
