#include "plugin/LightShadow.h"

#include "technique/DepthFormatGl.h"
#include "technique/Techniques.h"

#include "shadowmap/ShadowViewSettings.h"

#include <epoxy/gl.h>

#include <cmath>
#include <optional>
#include <string>

namespace shadowmap {

void LightShadow::ensureMap() {
    const MapShape shape = mapProjection(frame.kind)->shape(*this);
    const GLenum target = shape.target == MapShape::Target::Cube      ? GL_TEXTURE_CUBE_MAP
                          : shape.target == MapShape::Target::Array2D ? GL_TEXTURE_2D_ARRAY
                                                                      : GL_TEXTURE_2D;
    const GLenum format = glInternalFormat(settings.depthFormat);
    if (!map.id() || map.width() != settings.resolution || static_cast<GLenum>(map.internalFormat()) != format ||
        map.target() != target || map.layers() != shape.arrayLayers()) {
        map = target == GL_TEXTURE_CUBE_MAP ? engine::gl::Texture::createCube(format, settings.resolution)
              : target == GL_TEXTURE_2D_ARRAY
                  ? engine::gl::Texture::create2DArray(format, settings.resolution, settings.resolution, shape.arrayLayers())
                  : engine::gl::Texture::create2D(format, settings.resolution, settings.resolution);
        map.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        map.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        renderedKey = 0;  // a new texture holds nothing yet
        renderedCascadeKeys.clear();
        mapLayers = {};  // a view of the texture just replaced
    }
    // Reversed Z compares the other way round (lit where r >= stored: near is 1).
    map.setParameter(GL_TEXTURE_COMPARE_FUNC, settings.reversedZ ? GL_GEQUAL : GL_LEQUAL);
    const GLint filter = mapLookupFor(settings).bilinearCompare() ? GL_LINEAR : GL_NEAREST;
    map.setParameter(GL_TEXTURE_MIN_FILTER, filter);
    map.setParameter(GL_TEXTURE_MAG_FILTER, filter);
}

namespace {

// The anisotropy a mipmapped moments map is read with, where the GL filters anisotropically
// (GL 4.6, or the EXT/ARB extension): 16 samples along a receiver seen at a grazing angle,
// the most any GL promises (GL_MAX_TEXTURE_MAX_ANISOTROPY is at least 16 where supported).
constexpr float kMomentsAnisotropy = 16.0f;

bool filtersAnisotropically() {
    return epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") ||
           epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic");
}

GLenum momentsFormat(int channels) { return channels == 2 ? GL_RG32F : GL_RGBA32F; }

int momentsLevels(const LightShadow& light, const MapShape& shape) {
    if (shape.target != MapShape::Target::Texture2D || !light.settings.momentsMipmaps) return 1;
    int levels = 1;
    for (int size = light.settings.resolution; size > 1; size /= 2) ++levels;
    return levels;
}

} // namespace

void LightShadow::ensureMoments() {
    const int channels = mapLookupFor(settings).momentChannels();
    if (channels == 0) {
        moments = {};
        mapLayers = {};
        return;
    }
    const MapShape shape = mapProjection(frame.kind)->shape(*this);
    const GLenum target = shape.target == MapShape::Target::Cube      ? GL_TEXTURE_CUBE_MAP
                          : shape.target == MapShape::Target::Array2D ? GL_TEXTURE_2D_ARRAY
                                                                      : GL_TEXTURE_2D;
    const GLenum format = momentsFormat(channels);
    const int levels = momentsLevels(*this, shape);
    const int size = settings.resolution;
    if (!moments.id() || moments.width() != size || static_cast<GLenum>(moments.internalFormat()) != format ||
        moments.target() != target || moments.layers() != shape.arrayLayers() || moments.levels() != levels) {
        moments = target == GL_TEXTURE_CUBE_MAP ? engine::gl::Texture::createCube(format, size)
                  : target == GL_TEXTURE_2D_ARRAY
                      ? engine::gl::Texture::create2DArray(format, size, size, shape.arrayLayers())
                      : engine::gl::Texture::create2D(format, size, size, levels);
        moments.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        moments.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        moments.setParameter(GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        moments.setParameter(GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
        moments.setParameter(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        if (levels > 1 && filtersAnisotropically())
            moments.setParameterf(GL_TEXTURE_MAX_ANISOTROPY, kMomentsAnisotropy);
        // The moments are made with the map's passes: new ones hold nothing until those run.
        renderedKey = 0;
        renderedCascadeKeys.clear();
    }
    if (!mapLayers.id()) {
        GLuint view = 0;
        glGenTextures(1, &view);
        const int layers = shape.target == MapShape::Target::Cube ? engine::kCubeFaces : shape.arrayLayers();
        glTextureView(view, GL_TEXTURE_2D_ARRAY, map.id(), map.internalFormat(), 0, 1, 0, layers);
        mapLayers = engine::gl::Texture::wrap(view);
    }
}

engine::TextureDesc LightShadow::momentsDesc() const {
    const MapShape shape = mapProjection(frame.kind)->shape(*this);
    engine::TextureDesc desc{settings.resolution, settings.resolution,
                             moments.internalFormat() == GL_RG32F ? engine::TextureFormat::RG32F
                                                                  : engine::TextureFormat::RGBA32F,
                             shape.arrayLayers(), shape.target == MapShape::Target::Cube};
    return desc;
}

nlohmann::json LightShadow::settingsJson() const {
    return {{"variant", toString(settings.variant)},
            {"resolution", settings.resolution},
            {"depth_format", toString(settings.depthFormat)},
            {"filter", toString(settings.filter)},
            {"polygon_offset", {jsonNumber(settings.effectivePolygonOffset().x), jsonNumber(settings.effectivePolygonOffset().y)}},
            {"dimming", jsonNumber(settings.dimming)}};
}

void LightShadow::ensureVisibility(int width, int height) {
    if (visibility.id() && visibility.width() == width && visibility.height() == height) return;
    visibility = engine::gl::Texture::create2D(GL_R8, width, height);
    visibility.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    visibility.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    visibilityKey = 0;
    if (!volumeFill) volumeFill = engine::gl::Query::create(GL_SAMPLES_PASSED);
}

void LightShadow::ensureStencilCount(int width, int height) {
    if (stencilCount.id() && stencilCount.width() == width && stencilCount.height() == height) return;
    stencilCount = engine::gl::Texture::create2D(GL_R8, width, height);
    stencilCountKey = 0;
}

nlohmann::json LightShadow::stats() const {
    nlohmann::json out = settingsJson();
    out.update({{"light", name},
                {"slot", slot},
                {"map", frame.kind == MapKind::None     ? "none"
                        : frame.kind == MapKind::Screen ? "volumes"
                                                        : mapProjection(frame.kind)->name()},
                {"faces_rendered", frame.facesRendered},
                {"faces_skipped", frame.facesSkipped},
                {"draws", frame.draws},
                {"triangles", frame.triangles},
                {"casters_culled", frame.castersCulled},
                {"casters_unseen", frame.castersUnseen}});
    if (!frame.skipReason.empty()) out["skip_reason"] = frame.skipReason;
    if (const DepthTechnique* technique = depthTechnique(settings.variant)) technique->addStats(*this, out);
    if (frame.kind != MapKind::None) out["cache"] = frame.cacheHit ? "hit" : "miss";
    if (frame.kind == MapKind::Screen) {
        out["silhouette_edges"] = frame.silhouetteEdges;
        out["cap_triangles"] = frame.capTriangles;
        out["casters_extruded_on_gpu"] = frame.gpuVolumeCasters;
        out["casters_z_pass"] = frame.zPassVolumeCasters;
        // The pass's fill: 0 when it drew no volume or kept last frame's visibility; null
        // when the GPU has not finished it yet (the stats of an untimed frame).
        if (frame.volumeFillQueried) {
            const std::optional<std::uint64_t> fill = volumeFill.resultIfReady();
            out["stencil_fragments"] = fill ? nlohmann::json(*fill) : nlohmann::json(nullptr);
        } else {
            out["stencil_fragments"] = 0;
        }
    }
    if (const MapProjection* projection = mapProjection(frame.kind)) projection->addStats(*this, out);
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
    out.castsShadows = settings.variant != Variant::None;
    // The settings API's printer, so the tools read them back with its parser (usedSettings).
    out.settings = printUsedSettings(settings);
    (type == engine::Light::Type::Directional ? out.angularDiameter : out.lightRadius) = settings.lightSize(type);
    // volume: no map to show; its passes still say what it cost.
    out.hasMap = frame.kind != MapKind::None && frame.kind != MapKind::Screen;
    if (frame.kind == MapKind::Screen) {
        out.hasScreenVisibility = true;
        out.stencilCount = frame.stencilCount;
        out.renderedThisFrame = !frame.cacheHit;
        out.passes = frame.passes;
    }
    out.skipReason = frame.skipReason;
    out.cube = frame.kind == MapKind::Cube;
    if (const MapProjection* projection = mapProjection(frame.kind)) projection->describe(*this, out);
    if (out.hasMap) {
        out.renderedThisFrame = !frame.cacheHit;
        out.map = frame.map;
        out.passes = frame.passes;
    }
    return out;
}

} // namespace shadowmap
