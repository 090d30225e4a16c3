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
        // In the light's frustum and in front of the camera; beside the screen too: the
        // samples are a coarse grid, and a receiver that reaches into view from beside it
        // (a lamp's pool at the screen's edge, near the camera) would otherwise be sized by
        // its far samples only. Off-screen points size the map as if seen there: a larger
        // map, never a coarser one.
        if (!insideClip(light) || !(camera.w > 0.0) || camera.z < -camera.w || camera.z > camera.w) continue;
        for (int axis = 0; axis < 2; ++axis) {
            glm::dvec4 stepped = light;
            stepped[axis] += kStep * light.w;
            const glm::dvec4 world = lightToWorld * stepped;
            // Pixels per unit of the map's NDC; a texel of a res-sized map is 2 / res of it.
            const double pixelsPerNdc = glm::length(pixel(glm::dvec3(world) / world.w) - pixel(point)) / kStep;
            needed = std::max(needed, 2.0 * pixelsPerNdc);
        }
    }
    return needed * kMatchedSampleMargin;
}

std::vector<glm::dvec3> receiverSamples(const glm::dmat4& lightViewProjection, std::span<const engine::Aabb> receivers,
                                        int raysPerSide) {
    const glm::dmat4 toWorld = glm::inverse(lightViewProjection);
    const engine::Aabb reach = frustumBounds(lightViewProjection);
    std::vector<engine::Aabb> near;  // the receivers the light's frustum may reach
    for (const engine::Aabb& box : receivers)
        if (!reach.empty() && !glm::any(glm::greaterThan(glm::max(box.min, reach.min), glm::min(box.max, reach.max))))
            near.push_back(box);
    std::vector<glm::dvec3> points;
    if (near.empty() || raysPerSide < 2) return points;
    const auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 world = toWorld * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(world) / world.w;
    };
    for (int row = 0; row < raysPerSide; ++row)
        for (int column = 0; column < raysPerSide; ++column) {
            const double x = -1.0 + 2.0 * column / (raysPerSide - 1), y = -1.0 + 2.0 * row / (raysPerSide - 1);
            const glm::dvec3 from = unproject(x, y, -1.0), to = unproject(x, y, 1.0);
            const glm::dvec3 direction = to - from;
            // Where the ray enters each box within [from, to] (slab test): the surfaces facing
            // the light, the first lit and those behind it in its shadow, whose edges the map
            // draws as finely.
            for (const engine::Aabb& box : near) {
                double enter = 0.0, leave = 1.0;
                for (int axis = 0; axis < 3 && enter <= leave; ++axis) {
                    if (std::abs(direction[axis]) < 1e-300) {
                        if (from[axis] < box.min[axis] || from[axis] > box.max[axis]) enter = 2.0;
                        continue;
                    }
                    double t0 = (box.min[axis] - from[axis]) / direction[axis];
                    double t1 = (box.max[axis] - from[axis]) / direction[axis];
                    if (t0 > t1) std::swap(t0, t1);
                    enter = std::max(enter, t0);
                    leave = std::min(leave, t1);
                }
                if (enter <= leave) points.push_back(from + direction * enter);
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
