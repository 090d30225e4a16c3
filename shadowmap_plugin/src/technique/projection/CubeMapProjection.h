#pragma once
// A point light's cube map: six 90-degree faces around the light, axis-aligned in world
// space (LightFrustum.h fitPointLight), looked up by the light-to-point direction with the
// distance mapped to the faces' depth (visibility.glsl shadowMapCube).
#include "technique/MapProjection.h"

namespace shadowmap {

class CubeMapProjection final : public MapProjection {
public:
    MapKind kind() const override { return MapKind::Cube; }
    const char* name() const override { return "cube"; }
    ProjectionFit fit(LightState& light, const PlanContext& context, const FrustumFitOptions& options) const override;
    MapShape shape(const LightState&) const override { return {MapShape::Target::Cube, engine::kCubeFaces}; }
    void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                     bool cacheMaps) const override;
    std::vector<MapLayer> layers(const LightState& light) const override;
    const LightView& finestView(const LightState& light) const override { return light.frame.pointViews.faces[0]; }
    bool packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                    HookGlsl::Lookup& lookup) const override;
    void addStats(const LightState& light, nlohmann::json& stats) const override;
    void describe(const LightState& light, engine::ShadowView& view) const override;
};

} // namespace shadowmap
