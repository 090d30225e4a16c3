#include "technique/projection/FittedMapProjection.h"

#include "technique/MapCacheKey.h"
#include "technique/NormalOffsetData.h"
#include "technique/SoftShadowLayers.h"
#include "technique/projection/WarpedView.h"
#include "technique/projection/FiniteMatrix.h"

#include "math/Texgen.h"

namespace shadowmap {

ProjectionFit FittedMapProjection::fit(LightState& light, const PlanContext& context,
                                       const FrustumFitOptions& options) const {
    LightShadowFrame& plan = light.frame;
    const engine::LightInstance& placed = context.scene.lightInstances[light.slot];
    const engine::Light& source = context.scene.lights[placed.light];
    if (light.type == engine::Light::Type::Spot)
        plan.view = fitSpotLight(placed, source, context.bounds, options);
    else if (light.settings.projection == Projection::Lispsm)
        plan.view = fitWarpedView(light, context, options, std::nullopt, &plan.lispsm);
    else
        plan.view = fitDirectionalLight(placed, source, context.bounds, options);
    if (!plan.view.clampWarning.empty()) plan.warnings.push_back(plan.view.clampWarning);
    return {plan.view.valid, plan.view.empty, plan.view.invalidReason};
}

void FittedMapProjection::decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                                      bool cacheMaps) const {
    light.frame.mapKey = withDepthSettings(mapCacheKey(light, scene, sceneGeneration), light.settings);
    light.frame.cacheHit = cacheMaps && light.frame.mapKey == light.renderedKey;
}

std::vector<MapLayer> FittedMapProjection::layers(const LightState& light) const {
    return {{-1, light.frame.view.viewProjection(), true, -1, light.frame.mapKey}};
}

bool FittedMapProjection::packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                                     HookGlsl::Lookup&) const {
    // Ee = Epo * V with Epo = S * P_light * L^-1, composed in double (Texgen.h).
    const glm::mat4 uploaded(eyePlanesForCamera(light.frame.view.texgenPlanes(), context.eyeToWorld));
    if (!isFinite(uploaded)) return false;
    block.eyePlanes[light.slot] = uploaded;
    block.softLayers[light.slot * kMaxCascades] = softLayer(light.frame.view, light);
    block.texelWidths[light.slot] = glm::vec4(texelWidthPerDepth(light.frame.view, light.settings.resolution),
                                              texelWidthPerDepthSquared(light.frame.view, light.settings.resolution),
                                              0.0f, 0.0f);
    block.lightInEye[light.slot] = lightInEye(light.frame.view, light.type, context.view);
    return true;
}

void FittedMapProjection::addStats(const LightState& light, nlohmann::json& stats) const {
    const LightView& view = light.frame.view;
    stats["near"] = view.nearPlane;
    stats["far"] = view.farPlane;
    // L (light -> world), column-major, so tools can reproduce the map's depths.
    std::vector<double> lightToWorld;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) lightToWorld.push_back(view.lightToWorld[column][row]);
    stats["light_to_world"] = lightToWorld;
    if (light.type == engine::Light::Type::Directional && light.settings.projection == Projection::Lispsm) {
        const LispsmFit& warp = light.frame.lispsm;
        stats["lispsm"] = {{"warped", view.warped},
                           {"sin_gamma", warp.sinGamma},
                           {"weight", warp.weight},
                           {"n", view.warped ? nlohmann::json(warp.n) : nlohmann::json("infinite")},
                           {"body_depth", warp.bodyDepth}};
    }
}

void FittedMapProjection::describe(const LightState& light, engine::ShadowView& out) const {
    const LightView& view = light.frame.view;
    out.layers.push_back({view.lightToWorld, view.projection, true, !light.frame.cacheHit});
    out.nearPlane = view.nearPlane;
    out.farPlane = view.farPlane;
}

} // namespace shadowmap
