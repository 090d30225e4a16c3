#include "technique/LightPlanner.h"
#include "technique/UnseenShadows.h"

#include "technique/Techniques.h"
#include "technique/projection/CascadedMapProjection.h"

#include "engine/scene/FrustumCull.h"

namespace shadowmap {

namespace {

// A directional light's cascade count this frame: the setting's, or with `auto` the count
// the view needs (CascadeFit.h autoCascadeCount), remembered for the next frame. The weighing
// fits one map and three cascade sets; while its inputs (camera, light, boxes, settings) stay
// as they were, last frame's answer is reused.
int cascadeCount(LightState& light, const PlanContext& context, const FrustumFitOptions& fit) {
    if (light.settings.cascades != kAutoCascades) return light.settings.cascades;
    // The warp is what spends a single map's texels near the camera (LispsmWarp.h).
    if (light.settings.projection == Projection::Lispsm) return 1;
    const engine::LightInstance& placed = context.scene.lightInstances[light.slot];
    const engine::FrameCamera& camera = context.camera;
    LightShadowFrame& plan = light.frame;
    plan.autoCascades = true;
    engine::Hasher inputs;
    inputs.add(context.everything.min);
    inputs.add(context.everything.max);
    inputs.add(camera.eyeToWorld);
    inputs.add(camera.projection);
    inputs.add(camera.height);
    inputs.add(placed.world);
    inputs.add(light.settings.resolution);
    inputs.add(light.settings.cascadeLambda);
    inputs.add(light.settings.cascadeBlend);
    inputs.add(light.settings.stable);
    inputs.add(light.settings.shadowDistance);
    inputs.add(light.settings.reversedZ);
    for (const auto* boxes : {&context.bounds.receivers, &context.bounds.casters}) {
        inputs.add(boxes->size());
        for (const engine::Aabb& box : *boxes) {
            inputs.add(box.min);
            inputs.add(box.max);
        }
    }
    if (light.autoCascadeCount > 0 && inputs.value() == light.cascadeNeedKey) {
        plan.cascadeNeed = light.cascadeNeed;
        plan.cascadeNeedReused = true;
        return light.autoCascadeCount;
    }
    plan.cascadeNeed = cascadeNeed(placed, context.scene.lights[placed.light], context.bounds, context.everything,
                                   {camera.eyeToWorld, camera.projection}, cascadeOptions(light.settings, fit),
                                   camera.height);
    light.cascadeNeed = plan.cascadeNeed;
    light.cascadeNeedKey = inputs.value();
    light.autoCascadeCount = autoCascadeCount(plan.cascadeNeed, light.autoCascadeCount);
    return light.autoCascadeCount;
}

} // namespace

ShadowBounds frameBounds(const engine::Scene& scene, const engine::FrameCamera& camera) {
    const glm::dmat4 cameraViewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    ShadowBounds bounds;
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (instance.castShadows) bounds.casters.push_back(instance.worldBounds);
        if (instance.receiveShadows && engine::boxIntersectsFrustum(cameraViewProjection, instance.worldBounds))
            bounds.receivers.push_back(instance.worldBounds);
    }
    return bounds;
}

engine::Aabb sceneBounds(const engine::Scene& scene) {
    engine::Aabb bounds;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        if (instance.castShadows || instance.receiveShadows) bounds.extend(instance.worldBounds);
    return bounds;
}

PlanContext planContext(const engine::Scene& scene, const engine::FrameCamera& camera) {
    PlanContext context{scene, camera, frameBounds(scene, camera), sceneBounds(scene)};
    context.visibleReceiverParts = visibleReceiverParts(context.bounds.receivers, camera);
    return context;
}

bool planLight(LightState& light, const PlanContext& context, int textureUnit, int maxTextureUnits) {
    LightShadowFrame& plan = light.frame;
    plan = {};
    const engine::LightInstance& placed = context.scene.lightInstances[light.slot];
    const engine::Light& source = context.scene.lights[placed.light];
    if (light.settings.variant == Variant::None) {
        plan.skipReason = "variant none";
        return false;
    }
    if (!source.emitsLight()) {
        plan.skipReason = "the light emits nothing";
        return false;
    }
    const auto noUnitLeft = [&] {
        if (textureUnit < maxTextureUnits) return false;
        plan.skipReason = "no texture unit left for its " +
                          std::string(light.settings.variant == Variant::Volume ? "visibility" : "map") +
                          " (GL_MAX_TEXTURE_IMAGE_UNITS " + std::to_string(maxTextureUnits) + ")";
        plan.warnings.push_back(plan.skipReason);
        return true;
    };
    if (light.settings.variant == Variant::Volume) {
        // Exact and hard: no map, so nothing of a map's settings applies (said once).
        if (light.settings.filter != Filter::Pcf && light.settings.filter != Filter::Nearest)
            plan.warnings.push_back(std::string("variant volume gives hard shadows: filter \"") +
                                    toString(light.settings.filter) + "\" ignored");
        if (noUnitLeft()) return false;
        plan.kind = MapKind::Screen;
        return true;
    }
    const bool directional = light.type == engine::Light::Type::Directional;
    // Cascades slice a directional light's parallel projection; a spot or point light's
    // perspective already spends its texels near the light (said once when set; auto is silent).
    if (!directional && light.settings.cascades > 1)
        plan.warnings.push_back("cascades apply to directional lights only: " +
                                std::to_string(light.settings.cascades) + " ignored");
    if (!directional && light.settings.shadowDistance > 0.0)
        plan.warnings.push_back("shadow_distance applies to directional lights only: ignored");
    // Forced near/far and reversed Z (shadowmap/ShadowSettings.h). A directional light's depth is
    // linear and fitted to what it must hold: forced planes are ignored there (said once).
    FrustumFitOptions fitOptions;
    fitOptions.reversedZ = light.settings.reversedZ;
    if (directional) {
        if (light.settings.nearPlane > 0.0 || light.settings.farPlane > 0.0)
            plan.warnings.push_back("near_plane/far_plane apply to spot and point lights; ignored for a directional light");
        plan.cascadeCount = cascadeCount(light, context, fitOptions);
    } else {
        fitOptions.nearPlane = light.settings.nearPlane;
        fitOptions.farPlane = light.settings.farPlane;
    }
    const MapProjection& projection = projectionFor(light.type, plan.cascadeCount, light.settings.shadowDistance);
    const ProjectionFit fit = projection.fit(light, context, fitOptions);
    if (!fit.valid) {
        // Never upload NaN: a degenerate light loses its shadow, loudly.
        plan.skipReason = "no shadow: " + fit.invalidReason;
        plan.warnings.push_back(plan.skipReason);
        return false;
    }
    if (fit.empty) {
        plan.skipReason = "no visible receiver in the light's frustum";
        plan.emptyFrustum = true;
        return false;
    }
    if (noUnitLeft()) return false;
    plan.kind = projection.kind();
    return true;
}

void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration, bool cacheMaps) {
    mapProjection(light.frame.kind)->decideCache(light, scene, sceneGeneration, cacheMaps);
}

} // namespace shadowmap
