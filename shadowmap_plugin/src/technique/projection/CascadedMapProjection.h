#pragma once
// A directional light's cascades: the view depth split into up to kMaxCascades slices, one
// fitted map each, as layers of one 2D array map (CascadeFit.h). A pixel reads the cascade
// its view depth falls in, blending into the next near the boundary (visibility.glsl). Each
// layer is cached on its own: a stable far cascade keeps its depth while nearer ones follow
// the camera.
#include "technique/MapProjection.h"

namespace shadowmap {

// The cascade fit's options for these settings and depth-range options.
CascadeOptions cascadeOptions(const ShadowSettings& settings, const FrustumFitOptions& fit);

// Where a directional light's shadows fade out (shadow_distance, shadow_fade), in view depth:
// fully shadowed up to start, fully lit from end on; end 0: no limit.
struct ShadowFade {
    double start = 0.0, end = 0.0;
};
ShadowFade shadowFade(const ShadowSettings& settings);

class CascadedMapProjection final : public MapProjection {
public:
    MapKind kind() const override { return MapKind::Cascades; }
    const char* name() const override { return "cascades"; }
    ProjectionFit fit(LightState& light, const PlanContext& context, const FrustumFitOptions& options) const override;
    MapShape shape(const LightState& light) const override {
        return {MapShape::Target::Array2D, static_cast<int>(light.frame.cascades.cascades.size())};
    }
    void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                     bool cacheMaps) const override;
    std::vector<MapLayer> layers(const LightState& light) const override;
    const LightView& finestView(const LightState& light) const override;
    bool packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                    HookGlsl::Lookup& lookup) const override;
    void addShadeKey(const LightState& light, engine::Hasher& key) const override;
    void addStats(const LightState& light, nlohmann::json& stats) const override;
    void describe(const LightState& light, engine::ShadowView& view) const override;
};

} // namespace shadowmap
