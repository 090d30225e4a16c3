#include "technique/MapCacheKey.h"

#include "technique/Techniques.h"

#include "engine/scene/FrustumCull.h"
#include "engine/util/Hasher.h"

namespace shadowmap {

namespace {

void addSettings(engine::Hasher& hasher, const LightState& light, std::uint64_t sceneGeneration) {
    hasher.add(sceneGeneration);
    const ShadowSettings& s = light.settings;
    hasher.add(static_cast<int>(s.variant));
    hasher.add(s.resolution);
    hasher.add(static_cast<int>(s.depthFormat));
    hasher.add(s.effectivePolygonOffset().x);
    hasher.add(s.effectivePolygonOffset().y);
    hasher.add(s.standardPolygonOffset().x);
    hasher.add(s.standardPolygonOffset().y);
    hasher.add(static_cast<int>(light.frame.kind));
    // The levels drawn are chosen from it, the views and the casters' boxes and transforms.
    hasher.add(s.casterLod);
    // vsm, evsm: the moments made with the map hold its blur and warp.
    if (readsMoments(s.filter)) {
        hasher.add(static_cast<int>(s.filter));
        hasher.add(s.filterRadius);
        hasher.add(s.evsmExponents);
        hasher.add(s.momentsMipmaps);
    }
}

// What the light's passes draw with any of `views` (the casters, and the receivers that cast
// nothing where the depth technique draws those too): which mesh, where.
void addCasters(engine::Hasher& hasher, const LightState& light, const engine::Scene& scene,
                const std::vector<glm::dmat4>& views) {
    const DepthTechnique* technique = depthTechnique(light.settings.variant);
    const bool withReceivers = technique && technique->drawsNonCastingReceivers();
    for (const glm::dmat4& view : views) hasher.add(view);
    for (std::size_t i = 0; i < scene.meshInstances.size(); ++i) {
        const engine::MeshInstance& instance = scene.meshInstances[i];
        if (!instance.castShadows && !(withReceivers && instance.receiveShadows)) continue;
        bool inside = false;
        for (const glm::dmat4& view : views)
            inside = inside || engine::boxIntersectsFrustum(view, instance.worldBounds);
        if (!inside) continue;
        hasher.add(i);
        hasher.add(instance.mesh);
        hasher.add(instance.world);
        // A skinned or morphed caster deforms without moving (its world stays identity):
        // the revision changes whenever its posed vertices do.
        hasher.add(instance.revision);
    }
}

} // namespace

std::uint64_t mapCacheKey(const LightState& light, const engine::Scene& scene,
                          std::uint64_t sceneGeneration) {
    engine::Hasher hasher;
    addSettings(hasher, light, sceneGeneration);
    std::vector<glm::dmat4> views;  // the view-projections the depth passes draw with
    if (light.frame.kind == MapKind::Map2D) {
        views.push_back(light.frame.view.viewProjection());
    } else if (light.frame.kind == MapKind::Cascades) {
        for (const LightView& cascade : light.frame.cascades.cascades) {
            hasher.add(cascade.empty);
            if (!cascade.empty) views.push_back(cascade.viewProjection());
        }
    } else {
        for (const LightView& face : light.frame.pointViews.faces) {
            hasher.add(face.empty);
            if (!face.empty) views.push_back(face.viewProjection());
        }
    }
    addCasters(hasher, light, scene, views);
    return hasher.value();
}

std::uint64_t cascadeCacheKey(const LightState& light, int cascade, const engine::Scene& scene,
                              std::uint64_t sceneGeneration) {
    engine::Hasher hasher;
    addSettings(hasher, light, sceneGeneration);
    hasher.add(cascade);
    hasher.add(light.frame.cascades.cascades.size());
    const LightView& view = light.frame.cascades.cascades[cascade];
    hasher.add(view.empty);
    if (!view.empty) addCasters(hasher, light, scene, {view.viewProjection()});
    return hasher.value();
}

std::uint64_t withDepthSettings(std::uint64_t key, const ShadowSettings& settings) {
    engine::Hasher hasher;
    hasher.add(key);
    hasher.add(settings.reversedZ);
    hasher.add(settings.polygonOffsetClamp);
    return hasher.value();
}

} // namespace shadowmap
