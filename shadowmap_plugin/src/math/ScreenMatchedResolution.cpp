#include "math/ScreenMatchedResolution.h"

#include <algorithm>
#include <cmath>

namespace shadowmap {

namespace {

bool insideClip(const glm::dvec4& clip) {
    return clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
}

} // namespace

double screenMatchedResolution(const glm::dmat4& lightViewProjection, const glm::dmat4& cameraViewProjection,
                               int width, int height, std::span<const glm::dvec3> points) {
    const glm::dmat4 lightToWorld = glm::inverse(lightViewProjection);
    const auto pixel = [&](const glm::dvec3& world) {
        const glm::dvec4 clip = cameraViewProjection * glm::dvec4(world, 1.0);
        return glm::dvec2(clip.x / clip.w * width * 0.5, clip.y / clip.w * height * 0.5);
    };
    // A small step of NDC, for the derivative: the map's texels are far smaller than the
    // map, so the linear change at the point is what a texel spans.
    constexpr double kStep = 1e-4;
    double needed = 0.0;
    for (const glm::dvec3& point : points) {
        const glm::dvec4 light = lightViewProjection * glm::dvec4(point, 1.0);
        const glm::dvec4 camera = cameraViewProjection * glm::dvec4(point, 1.0);
        if (!insideClip(light) || !insideClip(camera) || camera.z < -camera.w || camera.z > camera.w) continue;
        for (int axis = 0; axis < 2; ++axis) {
            glm::dvec4 stepped = light;
            stepped[axis] += kStep * light.w;
            const glm::dvec4 world = lightToWorld * stepped;
            // Pixels per unit of the map's NDC; a texel of a res-sized map is 2 / res of it.
            const double pixelsPerNdc = glm::length(pixel(glm::dvec3(world) / world.w) - pixel(point)) / kStep;
            needed = std::max(needed, 2.0 * pixelsPerNdc);
        }
    }
    return needed;
}

std::vector<glm::dvec3> receiverSamples(const engine::Aabb& frustumBounds, std::span<const engine::Aabb> receivers) {
    std::vector<glm::dvec3> points;
    for (const engine::Aabb& receiver : receivers) {
        const glm::dvec3 low = glm::max(receiver.min, frustumBounds.min);
        const glm::dvec3 high = glm::min(receiver.max, frustumBounds.max);
        if (glm::any(glm::greaterThan(low, high))) continue;
        for (int i = 0; i < 27; ++i) {
            const glm::dvec3 t(i % 3 * 0.5, i / 3 % 3 * 0.5, i / 9 * 0.5);
            points.push_back(low + (high - low) * t);
        }
    }
    return points;
}

engine::Aabb frustumBounds(const glm::dmat4& viewProjection) {
    const glm::dmat4 inverse = glm::inverse(viewProjection);
    engine::Aabb bounds;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 ndc(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0, 1.0);
        const glm::dvec4 world = inverse * ndc;
        const glm::dvec3 point = glm::dvec3(world) / world.w;
        if (!(std::abs(world.w) > 0.0) || !std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
            return {};
        bounds.extend(point);
    }
    return bounds;
}

} // namespace shadowmap
