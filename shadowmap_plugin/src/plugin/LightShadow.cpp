#include "plugin/LightShadow.h"

#include "plugin/DepthFormatGl.h"

#include <epoxy/gl.h>

#include <cmath>
#include <string>

namespace shadowmap {

void LightShadow::ensureMap() {
    const bool cube = type == engine::Light::Type::Point;
    const int layers = frame.kind == MapKind::Cascades ? static_cast<int>(frame.cascades.cascades.size()) : 1;
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : frame.kind == MapKind::Cascades ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
    const GLenum format = glInternalFormat(settings.depthFormat);
    if (!map.id() || map.width() != settings.resolution || static_cast<GLenum>(map.internalFormat()) != format ||
        map.target() != target || map.layers() != layers) {
        map = cube ? engine::gl::Texture::createCube(format, settings.resolution)
              : target == GL_TEXTURE_2D_ARRAY
                  ? engine::gl::Texture::create2DArray(format, settings.resolution, settings.resolution, layers)
                  : engine::gl::Texture::create2D(format, settings.resolution, settings.resolution);
        map.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        map.setParameter(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        map.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        renderedKey = 0;  // a new texture holds nothing yet
        renderedCascadeKeys.clear();
    }
    renderedCascadeKeys.resize(frame.kind == MapKind::Cascades ? layers : 0, 0);
    // GL_LINEAR on a depth-compare texture is 2x2 percentage-closer filtering.
    const GLint filter = settings.filter == Filter::Pcf ? GL_LINEAR : GL_NEAREST;
    map.setParameter(GL_TEXTURE_MIN_FILTER, filter);
    map.setParameter(GL_TEXTURE_MAG_FILTER, filter);
}

std::string LightShadow::mapResource() const { return "shadow_map_" + std::to_string(slot); }
namespace {
// Cube faces in GL order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), as pass names show them.
constexpr const char* kFaceNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
// Cascades: "_c0" (nearest) .. "_c3".
std::string layerSuffix(MapKind kind, int layer) {
    if (layer < 0) return "";
    return kind == MapKind::Cascades ? "_c" + std::to_string(layer) : std::string("_") + kFaceNames[layer];
}
} // namespace

std::string LightShadow::depthPass(int layer) const {
    return "shadow_" + std::to_string(slot) + "_" + name + layerSuffix(frame.kind, layer);
}
std::string LightShadow::firstLayerPass(int layer) const { return depthPass(layer) + "_first_layer"; }
std::string LightShadow::firstLayerResource(int layer) const {
    return "shadow_first_layer_" + std::to_string(slot) + layerSuffix(frame.kind, layer);
}

std::vector<std::string> LightShadow::depthPasses() const {
    std::vector<std::string> passes;
    auto addLayer = [&](int layer, bool drawsCasters) {
        // Woo draws a first layer only where there are casters to draw (ShadowMapPlugin.cpp).
        if (settings.variant == Variant::Woo && drawsCasters) passes.push_back(firstLayerPass(layer));
        passes.push_back(depthPass(layer));
    };
    if (frame.kind == MapKind::Map2D) addLayer(-1, true);
    if (frame.kind == MapKind::Cascades)
        for (std::size_t c = 0; c < frame.cascades.cascades.size(); ++c)
            if (c >= frame.cascadeHits.size() || !frame.cascadeHits[c])  // a kept layer has no pass
                addLayer(static_cast<int>(c), !frame.cascades.cascades[c].empty);
    if (frame.kind == MapKind::Cube)
        for (int face = 0; face < 6; ++face) addLayer(face, !frame.pointViews.faces[face].empty);
    return passes;
}

nlohmann::json LightShadow::settingsJson() const {
    return {{"variant", toString(settings.variant)},
            {"resolution", settings.resolution},
            {"depth_format", toString(settings.depthFormat)},
            {"filter", toString(settings.filter)},
            {"polygon_offset", {jsonNumber(settings.effectivePolygonOffset().x), jsonNumber(settings.effectivePolygonOffset().y)}},
            {"dimming", jsonNumber(settings.dimming)}};
}

nlohmann::json LightShadow::stats() const {
    nlohmann::json out = settingsJson();
    out.update({{"light", name},
                {"slot", slot},
                {"map", frame.kind == MapKind::None       ? "none"
                        : frame.kind == MapKind::Cube     ? "cube"
                        : frame.kind == MapKind::Cascades ? "cascades"
                                                          : "2d"},
                {"faces_rendered", frame.facesRendered},
                {"faces_skipped", frame.facesSkipped},
                {"draws", frame.draws},
                {"triangles", frame.triangles},
                {"casters_culled", frame.castersCulled}});
    if (!frame.skipReason.empty()) out["skip_reason"] = frame.skipReason;
    if (settings.variant == Variant::Backface) out["open_casters"] = frame.openCasters;
    if (frame.kind != MapKind::None) out["cache"] = frame.cacheHit ? "hit" : "miss";
    if (frame.kind == MapKind::Map2D) {
        out["near"] = frame.view.nearPlane;
        out["far"] = frame.view.farPlane;
        // L (light -> world), column-major, so tools can reproduce the map's depths.
        std::vector<double> lightToWorld;
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) lightToWorld.push_back(frame.view.lightToWorld[column][row]);
        out["light_to_world"] = lightToWorld;
    } else if (frame.kind == MapKind::Cube) {
        out["near"] = frame.pointViews.nearPlane;
        out["far"] = frame.pointViews.farPlane;
    } else if (frame.kind == MapKind::Cascades) {
        // Per cascade: the view depths it covers and its map's extent and depth range, in
        // world units, so a reader sees where the texels went.
        nlohmann::json cascades = nlohmann::json::array();
        const CascadeViews& views = frame.cascades;
        for (std::size_t c = 0; c < views.cascades.size(); ++c) {
            const LightView& view = views.cascades[c];
            cascades.push_back({{"from", views.splits[c]},
                                {"to", views.splits[c + 1]},
                                {"rendered", !view.empty},
                                {"cache", c < frame.cascadeHits.size() && frame.cascadeHits[c] ? "hit" : "miss"},
                                {"width", view.empty ? 0.0 : 2.0 / view.projection[0][0]},
                                {"depth", view.farPlane - view.nearPlane}});
        }
        out["cascades"] = cascades;
    }
    if (frame.autoCascades) {
        // cascades: auto: what it weighed for 1..4 (CascadeNeed; null where a count gives no
        // map) and the count it chose.
        const auto perCount = [](const double (&values)[kMaxCascades + 1]) {
            nlohmann::json list = nlohmann::json::array();
            for (int count = 1; count <= kMaxCascades; ++count)
                list.push_back(std::isfinite(values[count]) ? nlohmann::json(values[count]) : nlohmann::json(nullptr));
            return list;
        };
        out["cascades_auto"] = {{"count", frame.cascadeCount},
                                {"reused", frame.cascadeNeedReused},
                                {"texels_per_pixel", perCount(frame.cascadeNeed.texelsPerPixel)},
                                {"mean_texel", perCount(frame.cascadeNeed.meanTexel)}};
    }
    return out;
}

engine::ShadowView LightShadow::view() const {
    engine::ShadowView out;
    out.slot = slot;
    out.name = name;
    out.variant = toString(settings.variant);
    out.settings = settingsJson();
    out.hasMap = frame.kind != MapKind::None;
    out.skipReason = frame.skipReason;
    out.cube = frame.kind == MapKind::Cube;
    if (frame.kind == MapKind::Map2D) {
        out.layers.push_back({frame.view.lightToWorld, frame.view.projection, true});
        out.nearPlane = frame.view.nearPlane;
        out.farPlane = frame.view.farPlane;
    } else if (frame.kind == MapKind::Cascades) {
        for (const LightView& cascade : frame.cascades.cascades)
            out.layers.push_back({cascade.lightToWorld, cascade.projection, !cascade.empty});
        out.cascadeSplits = frame.cascades.splits;
        out.nearPlane = frame.cascades.cascades.front().nearPlane;
        out.farPlane = frame.cascades.cascades.front().farPlane;
    } else if (frame.kind == MapKind::Cube) {
        for (const LightView& face : frame.pointViews.faces)
            out.layers.push_back({face.lightToWorld, face.projection, !face.empty});
        out.nearPlane = frame.pointViews.nearPlane;
        out.farPlane = frame.pointViews.farPlane;
    }
    if (out.hasMap) {
        out.renderedThisFrame = !frame.cacheHit;
        out.mapResource = mapResource();
        out.passes = depthPasses();
    }
    return out;
}

} // namespace shadowmap
