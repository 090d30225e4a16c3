#include "ProjectedDepth.h"

#include <algorithm>
#include <cmath>

namespace engine_view {

namespace {

// (s, t) in [0,1]^2 on a 2D map (t = 0 at GL's first row); false when the map has no
// texel for p.
bool mapLookup(const ProjectedMap& map, const glm::dvec3& p, glm::dvec2& st) {
    const glm::dvec4 clip = map.viewProjection * glm::dvec4(p, 1.0);
    if (clip.w <= 0.0) return false;  // behind the light: never projected (no back-projection)
    st = glm::dvec2(clip) / clip.w * 0.5 + 0.5;
    return st.x >= 0.0 && st.x < 1.0 && st.y >= 0.0 && st.y < 1.0;
}

// OpenGL 4.5 core, table 8.19: the face and (sc, tc, ma) of a cube-map direction.
bool cubeLookup(const glm::dvec3& r, glm::dvec2& st, int& face) {
    const glm::dvec3 a = glm::abs(r);
    double sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x >= 0 ? 0 : 1;
        ma = a.x, sc = r.x >= 0 ? -r.z : r.z, tc = -r.y;
    } else if (a.y >= a.z) {
        face = r.y >= 0 ? 2 : 3;
        ma = a.y, sc = r.x, tc = r.y >= 0 ? r.z : -r.z;
    } else {
        face = r.z >= 0 ? 4 : 5;
        ma = a.z, sc = r.z >= 0 ? r.x : -r.x, tc = -r.y;
    }
    if (ma <= 0.0) return false;
    st = glm::dvec2(sc / ma, tc / ma) * 0.5 + 0.5;
    st = glm::clamp(st, 0.0, 0.999999);
    return true;
}

} // namespace

Image projectDepthMap(const Image& shaded, const truth::SurfaceBuffer& surfaces, const ProjectedMap& map) {
    Image out = shaded;
    const int size = map.faceSize;
    const int stripWidth = map.kind == ProjectedMap::Kind::Cube ? size * engine::kCubeFaces : size;
    for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
        if (!surfaces.covered[i]) continue;
        std::uint8_t* pixel = &out.rgba[4 * i];
        glm::dvec2 st;
        int face = 0;
        const bool hit = map.kind == ProjectedMap::Kind::Map2D
                             ? mapLookup(map, surfaces.worldPosition[i], st)
                             : cubeLookup(surfaces.worldPosition[i] - map.position, st, face);
        if (!hit || size <= 0) {
            for (int c = 0; c < 3; ++c) pixel[c] = static_cast<std::uint8_t>(pixel[c] * 0.3);
            continue;
        }
        // t counts from GL's first row; the gray picture is top row first.
        const int column = std::min(static_cast<int>(st.x * size), size - 1);
        const int row = size - 1 - std::min(static_cast<int>(st.y * size), size - 1);
        const std::uint8_t gray = (*map.gray)[static_cast<std::size_t>(row) * stripWidth + face * size + column];
        for (int c = 0; c < 3; ++c) pixel[c] = static_cast<std::uint8_t>(0.75 * gray + 0.25 * pixel[c] + 0.5);
    }
    return out;
}

} // namespace engine_view
