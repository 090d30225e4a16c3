#include "plugin/LightShadow.h"

#include <epoxy/gl.h>

#include <charconv>
#include <cstdlib>
#include <string>

namespace shadowmap {

void LightShadow::ensureMap() {
    const bool cube = type == engine::Light::Type::Point;
    const GLenum format = glInternalFormat(settings.depthFormat);
    if (!map.id() || map.width() != settings.resolution ||
        static_cast<GLenum>(map.internalFormat()) != format || (map.target() == GL_TEXTURE_CUBE_MAP) != cube) {
        map = cube ? engine::gl::Texture::createCube(format, settings.resolution)
                   : engine::gl::Texture::create2D(format, settings.resolution, settings.resolution);
        map.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        map.setParameter(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        map.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        map.setParameter(GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        renderedKey = 0;  // a new texture holds nothing yet
    }
    // GL_LINEAR on a depth-compare texture is 2x2 percentage-closer filtering.
    const GLint filter = settings.filter == Filter::Pcf ? GL_LINEAR : GL_NEAREST;
    map.setParameter(GL_TEXTURE_MIN_FILTER, filter);
    map.setParameter(GL_TEXTURE_MAG_FILTER, filter);
}

namespace {

// A float setting as the decimal it was written as: float 0.4 widened to double would read
// 0.4000000059604645; its shortest float decimal reads 0.4.
double asWritten(float value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::strtod(std::string(text, end).c_str(), nullptr);
}

} // namespace

nlohmann::json LightShadow::stats() const {
    nlohmann::json out{{"light", name},
                       {"slot", slot},
                       {"variant", toString(settings.variant)},
                       {"resolution", settings.resolution},
                       {"depth_format", toString(settings.depthFormat)},
                       {"filter", toString(settings.filter)},
                       {"polygon_offset", {asWritten(settings.effectivePolygonOffset().x),
                                           asWritten(settings.effectivePolygonOffset().y)}},
                       {"dimming", asWritten(settings.dimming)},
                       {"map", frame.kind == MapKind::None ? "none"
                               : frame.kind == MapKind::Cube ? "cube"
                                                             : "2d"},
                       {"faces_rendered", frame.facesRendered},
                       {"faces_skipped", frame.facesSkipped},
                       {"draws", frame.draws},
                       {"triangles", frame.triangles},
                       {"casters_culled", frame.castersCulled}};
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
    }
    return out;
}

} // namespace shadowmap
