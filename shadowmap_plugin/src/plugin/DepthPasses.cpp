#include "plugin/DepthPasses.h"

#include "technique/DepthFormatGl.h"
#include "technique/Techniques.h"
#include "technique/UnseenShadows.h"

#include <cmath>

namespace shadowmap {

namespace {

// polygon_offset_clamp (a slope S) as glPolygonOffsetClamp's window-depth clamp for this
// light: factor * S * (window depth across one texel of a 45-degree surface) plus the units
// part, so the clamp only bites once the slope exceeds S. Perspective maps: taken at the
// nearest receiver, where a texel is smallest and the depth steepest (farther away the
// same clamp allows a steeper slope: it errs toward acne-free). Cascades share one style:
// the nearest cascade's texels are the smallest, so its clamp is the tightest. 0: no clamp.
float offsetClamp(const LightState& light, const MapProjection& projection) {
    const ShadowSettings& settings = light.settings;
    const glm::vec2 offset = settings.effectivePolygonOffset();
    if (!(settings.polygonOffsetClamp > 0.0f) || offset == glm::vec2(0.0f)) return 0.0f;
    const double perTexel = windowDepthPerTexel(projection.finestView(light), settings.resolution);
    // Float units are 2^(e-23) of the depth e: at most 2^-23 below 1 (reversed Z).
    const double units = std::abs(offset.y) * (settings.reversedZ ? std::ldexp(1.0, -23) : depthStep(settings.depthFormat));
    return static_cast<float>(std::abs(offset.x) * settings.polygonOffsetClamp * perTexel + units);
}

void addCounts(LightShadowFrame& plan, const DepthDrawCounts& counts) {
    plan.draws += counts.draws;
    plan.triangles += counts.triangles;
    plan.castersCulled += counts.castersCulled;
    plan.castersUnseen += counts.castersUnseen;
}

} // namespace

void addDepthPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle& map, DepthRenderer& renderer,
                    const std::vector<bool>& closedMeshes, const CasterLods* casterLods,
                    std::vector<std::uint64_t>& levelDraws, DepthPassStyle::Viewport atlasViewport) {
    const MapProjection& projection = *mapProjection(light.frame.kind);
    const DepthTechnique& technique = *depthTechnique(light.settings.variant);
    DepthPassStyle style;
    style.polygonOffset = light.settings.effectivePolygonOffset();
    style.reversedZ = light.settings.reversedZ;
    style.offsetClamp = offsetClamp(light, projection);
    style.atlasViewport = atlasViewport;
    technique.adjustStyle(light, {frame.scene(), closedMeshes}, style);
    if (light.settings.casterLod > 0.0) {
        style.casterLods = casterLods;
        style.lodTexelFraction = light.settings.casterLod;
        style.mapResolution = light.settings.resolution;
    }

    const std::vector<MapLayer> layers = projection.layers(light);
    // Rendered: layers drawn this frame; skipped: the rest (empty, or still right).
    for (const MapLayer& layer : layers) light.frame.facesRendered += layer.drawsCasters ? 1 : 0;
    light.frame.facesSkipped = projection.shape(light).layers - light.frame.facesRendered;
    const CasterDraw draw = [&renderer, &light, &frame, &levelDraws](engine::PassContext& context,
                                                                     const glm::dmat4& viewProjection,
                                                                     const DepthPassStyle& drawStyle) {
        const DepthDrawCounts counts = renderer.draw(frame, context, viewProjection, drawStyle);
        addCounts(light.frame, counts);
        if (levelDraws.size() < counts.levelDraws.size()) levelDraws.resize(counts.levelDraws.size());
        for (std::size_t l = 0; l < counts.levelDraws.size(); ++l) levelDraws[l] += counts.levelDraws[l];
    };
    for (const MapLayer& layer : layers) {
        // Only once its passes have run does the layer hold what its key says.
        std::uint64_t& recorded = layer.keySlot < 0 ? light.renderedKey : light.renderedCascadeKeys[layer.keySlot];
        recorded = 0;
        std::uint64_t* target = &recorded;
        const std::uint64_t key = layer.keyWhenDone;
        const std::size_t index = layerIndex(layer.layer);
        DepthPassStyle layerStyle = style;
        const bool culls = index < light.frame.unseenCasters.size() && !light.frame.unseenCasters[index].empty();
        if (culls) layerStyle.unseenCasters = &light.frame.unseenCasters[index];
        if (light.renderedUnseen.size() <= index) light.renderedUnseen.resize(index + 1);
        technique.addLayerPasses({frame.graph(), light, map, layer, layerStyle, draw,
                                  [target, key, &light, index] {
                                      if (key) *target = key;
                                      // What the layer now lacks (a later hit must not need it).
                                      light.renderedUnseen[index] = index < light.frame.unseenCasters.size()
                                                                        ? light.frame.unseenCasters[index]
                                                                        : std::vector<bool>{};
                                  },
                                  light.frame.passes});
    }
}

} // namespace shadowmap
