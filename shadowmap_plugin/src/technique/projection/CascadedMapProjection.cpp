#include "technique/projection/CascadedMapProjection.h"

#include "technique/MapCacheKey.h"
#include "technique/NormalOffsetData.h"
#include "technique/SoftShadowLayers.h"
#include "technique/projection/FiniteMatrix.h"
#include "technique/projection/WarpedView.h"

#include "math/Texgen.h"

#include <algorithm>

#include <limits>

namespace shadowmap {

ShadowFade shadowFade(const ShadowSettings& settings) {
    if (!(settings.shadowDistance > 0.0)) return {};
    return {settings.shadowDistance * (1.0 - settings.shadowFade), settings.shadowDistance};
}

CascadeOptions cascadeOptions(const ShadowSettings& settings, const FrustumFitOptions& fit) {
    CascadeOptions options;
    options.count = settings.cascades;
    options.lambda = settings.cascadeLambda;
    options.blend = settings.cascadeBlend;
    options.stable = settings.stable;
    options.maxDistance = settings.shadowDistance;
    options.resolution = settings.resolution;
    options.fit = fit;
    return options;
}

ProjectionFit CascadedMapProjection::fit(LightState& light, const PlanContext& context,
                                         const FrustumFitOptions& fitOptions) const {
    LightShadowFrame& plan = light.frame;
    const engine::LightInstance& placed = context.scene.lightInstances[light.slot];
    CascadeOptions options = cascadeOptions(light.settings, fitOptions);
    options.count = plan.cascadeCount;
    // A warp follows the camera, so a warped cascade cannot be a texel-snapped square: lispsm
    // cascades are fitted, each the warped view of its slice (WarpedView.h).
    const bool warped = light.settings.projection == Projection::Lispsm;
    if (warped) options.stable = false;
    plan.cascades = fitDirectionalCascades(placed, context.scene.lights[placed.light], context.bounds,
                                           context.everything,
                                           {context.camera.eyeToWorld, context.camera.projection}, options);
    if (warped && plan.cascades.valid && !plan.cascades.empty)
        for (int c = 0; c < static_cast<int>(plan.cascades.cascades.size()); ++c) {
            const glm::dvec2 slice(plan.cascades.splits[c], cascadeSliceFar(plan.cascades.splits, c, options));
            LightView view = fitWarpedView(light, context, fitOptions, slice, nullptr);
            if (!view.valid) return {false, true, view.invalidReason};
            plan.cascades.cascades[c] = std::move(view);
        }
    // Nothing to draw in any cascade (or no cascade: no visible receiver) is no map at all.
    bool empty = true;
    for (const LightView& cascade : plan.cascades.cascades) empty = empty && cascade.empty;
    return {plan.cascades.valid, empty, plan.cascades.invalidReason};
}

void CascadedMapProjection::decideCache(LightState& light, const engine::Scene& scene,
                                        std::uint64_t sceneGeneration, bool cacheMaps) const {
    LightShadowFrame& plan = light.frame;
    const std::size_t count = plan.cascades.cascades.size();
    plan.cascadeKeys.assign(count, 0);
    plan.cascadeHits.assign(count, false);
    light.renderedCascadeKeys.resize(count, 0);
    engine::Hasher combined;
    for (std::size_t c = 0; c < count; ++c) {
        plan.cascadeKeys[c] =
            withDepthSettings(cascadeCacheKey(light, static_cast<int>(c), scene, sceneGeneration), light.settings);
        plan.cascadeHits[c] = cacheMaps && plan.cascadeKeys[c] == light.renderedCascadeKeys[c];
        combined.add(plan.cascadeKeys[c]);
    }
    plan.mapKey = combined.value();
    plan.cacheHit = std::find(plan.cascadeHits.begin(), plan.cascadeHits.end(), false) == plan.cascadeHits.end();
}

std::vector<MapLayer> CascadedMapProjection::layers(const LightState& light) const {
    // One layer per cascade; one whose slice holds no receiver is cleared (reads "far").
    // Layers still right from an earlier frame keep their depth (before the cache decision
    // every layer is to be rendered, with no key yet).
    std::vector<MapLayer> out;
    const LightShadowFrame& frame = light.frame;
    const std::vector<LightView>& cascades = frame.cascades.cascades;
    for (std::size_t c = 0; c < cascades.size(); ++c) {
        const bool decided = c < frame.cascadeHits.size();
        if (decided && frame.cascadeHits[c]) continue;
        const int layer = static_cast<int>(c);
        out.push_back({layer, cascades[c].viewProjection(), !cascades[c].empty, layer,
                       decided ? frame.cascadeKeys[c] : 0});
    }
    return out;
}

const LightView& CascadedMapProjection::finestView(const LightState& light) const {
    // The nearest cascade that draws anything has the smallest texels.
    for (const LightView& view : light.frame.cascades.cascades)
        if (!view.empty) return view;
    return light.frame.cascades.cascades.front();
}

bool CascadedMapProjection::packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                                       HookGlsl::Lookup& lookup) const {
    const CascadeViews& views = light.frame.cascades;
    std::vector<glm::mat4> planes;  // per cascade, Ee as for a 2D map
    for (const LightView& cascade : views.cascades) {
        planes.emplace_back(eyePlanesForCamera(cascade.texgenPlanes(), context.eyeToWorld));
        if (!isFinite(planes.back())) return false;
    }
    const int count = static_cast<int>(planes.size());
    // The far view depth of each cascade; unused entries never match (visibility.glsl).
    for (int c = 0; c < kMaxCascades; ++c) {
        if (c < count) block.cascadePlanes[light.slot * kMaxCascades + c] = planes[c];
        if (c < count) block.softLayers[light.slot * kMaxCascades + c] = softLayer(views.cascades[c], light);
        block.texelWidths[light.slot][c] =
            c < count ? texelWidthPerDepth(views.cascades[c], light.settings.resolution) : 0.0f;
        block.cascadeFar[light.slot][c] =
            c < count ? static_cast<float>(views.splits[c + 1]) : std::numeric_limits<float>::max();
    }
    const ShadowFade fade = shadowFade(light.settings);
    block.cascadeBlend[light.slot] = glm::vec4(static_cast<float>(light.settings.cascadeBlend),
                                               static_cast<float>(views.splits.front()),
                                               static_cast<float>(fade.end), static_cast<float>(fade.start));
    block.lightInEye[light.slot] = lightInEye(views.cascades.front(), light.type, context.view);
    lookup.cascades = count;
    return true;
}

void CascadedMapProjection::addShadeKey(const LightState& light, engine::Hasher& key) const {
    // Which cascade a pixel reads (the splits) and how it fades into the next.
    for (const double split : light.frame.cascades.splits) key.add(split);
    key.add(light.settings.cascadeBlend);
    key.add(light.settings.shadowDistance);
    key.add(light.settings.shadowFade);
}

void CascadedMapProjection::addStats(const LightState& light, nlohmann::json& stats) const {
    // Per cascade: the view depths it covers and its map's extent and depth range, in world
    // units, so a reader sees where the texels went.
    nlohmann::json cascades = nlohmann::json::array();
    const LightShadowFrame& frame = light.frame;
    const CascadeViews& views = frame.cascades;
    for (std::size_t c = 0; c < views.cascades.size(); ++c) {
        const LightView& view = views.cascades[c];
        cascades.push_back({{"from", views.splits[c]},
                            {"to", views.splits[c + 1]},
                            {"rendered", !view.empty},
                            {"cache", c < frame.cascadeHits.size() && frame.cascadeHits[c] ? "hit" : "miss"},
                            {"warped", view.warped},
                            {"width", view.empty || view.warped ? 0.0 : 2.0 / view.projection[0][0]},
                            {"depth", view.farPlane - view.nearPlane}});
    }
    stats["cascades"] = cascades;
}

void CascadedMapProjection::describe(const LightState& light, engine::ShadowView& out) const {
    const LightShadowFrame& frame = light.frame;
    const CascadeViews& views = frame.cascades;
    for (std::size_t c = 0; c < views.cascades.size(); ++c) {
        const LightView& cascade = views.cascades[c];
        const bool kept = c < frame.cascadeHits.size() && frame.cascadeHits[c];
        out.layers.push_back({cascade.lightToWorld, cascade.projection, !cascade.empty, !kept});
    }
    out.cascadeCountReused = frame.autoCascades && frame.cascadeNeedReused;
    out.cascadeSplits = views.splits;
    out.nearPlane = views.cascades.front().nearPlane;
    out.farPlane = views.cascades.front().farPlane;
}

} // namespace shadowmap
