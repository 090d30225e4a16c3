#include "truth/Shimmer.h"

#include <cmath>

namespace truth {

namespace {

// Where world point p lands in `camera`'s image, in pixel coordinates (column, row; the
// centre of pixel (c, r) is (c, r), rows top first); false behind the camera or outside.
// Eye-relative first, so a scene far from the origin keeps its precision.
bool project(const engine::FrameCamera& camera, const glm::dvec3& p, glm::dvec2& pixel, double& eyeDepth) {
    const glm::dmat4& v = camera.eyeToWorld;
    const glm::dvec3 d = p - glm::dvec3(v[3]);
    const glm::dvec4 eye(glm::dot(glm::dvec3(v[0]), d), glm::dot(glm::dvec3(v[1]), d), glm::dot(glm::dvec3(v[2]), d), 1.0);
    const glm::dvec4 clip = camera.projection * eye;
    if (!(clip.w > 0.0)) return false;
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    pixel = {(ndc.x * 0.5 + 0.5) * camera.width - 0.5, (0.5 - ndc.y * 0.5) * camera.height - 0.5};
    eyeDepth = -eye.z;
    return pixel.x > -0.5 && pixel.y > -0.5 && pixel.x < camera.width - 0.5 && pixel.y < camera.height - 0.5;
}

// World size of one pixel at eye depth `depth` (perspective: grows with depth).
double pixelFootprint(const engine::FrameCamera& camera, double depth) {
    const bool perspective = camera.projection[2][3] != 0.0;
    return (perspective ? depth : 1.0) * 2.0 / (std::abs(camera.projection[1][1]) * camera.height);
}

} // namespace

ShimmerCount shimmerBetween(const ShimmerFrame& a, const ShimmerFrame& b) {
    ShimmerCount count;
    const SurfaceBuffer& sa = *a.surfaces;
    const SurfaceBuffer& sb = *b.surfaces;
    for (std::size_t p = 0; p < sa.pixelCount(); ++p) {
        if (!a.evaluated[p]) continue;
        glm::dvec2 at;
        double depth = 0.0;
        if (!project(sb.camera, sa.worldPosition[p], at, depth)) continue;
        const glm::dvec2 centre = glm::round(at);
        if (std::abs(at.x - centre.x) > kShimmerReprojection || std::abs(at.y - centre.y) > kShimmerReprojection)
            continue;
        const std::size_t q = static_cast<std::size_t>(centre.y) * sb.width + static_cast<std::size_t>(centre.x);
        if (!b.evaluated[q] || sb.instance[q] != sa.instance[p]) continue;
        if (glm::length(sb.worldPosition[q] - sa.worldPosition[p]) > pixelFootprint(sb.camera, depth)) continue;
        if (a.truth[p] != b.truth[q]) continue;
        ++count.compared;
        count.changed += (a.mask[p] >= 128) != (b.mask[q] >= 128);
    }
    return count;
}

} // namespace truth
