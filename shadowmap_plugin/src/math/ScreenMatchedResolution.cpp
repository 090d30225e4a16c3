#include "math/ScreenMatchedResolution.h"

#include <algorithm>
#include <cmath>

namespace shadowmap {

namespace {

// A surface this close to edge-on to the light (the sine of the angle between its texel
// directions in the map) has no measurable texel: as the truth's texel metric
// (tools/truth/TexelMetric.cpp) treats it, measured there independently of this code.
constexpr double kEdgeOnSine = 1e-3;

bool insideClip(const glm::dvec4& clip) {
    return clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
}

} // namespace

// The Jacobian of NDC = clip.xy / clip.w along two world directions (their clip images dA, dB).
glm::dmat2 divideJacobian(const glm::dvec4& clip, const glm::dvec4& dA, const glm::dvec4& dB) {
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return glm::dmat2((glm::dvec2(dA) - ndc * dA.w) / clip.w, (glm::dvec2(dB) - ndc * dB.w) / clip.w);
}

double screenMatchedResolution(const glm::dmat4& lightViewProjection, const glm::dmat4& cameraViewProjection,
                               int width, int height, std::span<const ReceiverSample> samples) {
    double needed = 0.0;
    for (const ReceiverSample& sample : samples) {
        const glm::dvec4 point(sample.point, 1.0);
        const glm::dvec4 light = lightViewProjection * point;
        const glm::dvec4 camera = cameraViewProjection * point;
        // In the light's frustum and in front of the camera; beside the screen too: the
        // samples are a coarse grid, and a receiver that reaches into view from beside it
        // (a lamp's pool at the screen's edge, near the camera) would otherwise be sized by
        // its far samples only. Off-screen points size the map as if seen there: a larger
        // map, never a coarser one.
        if (!insideClip(light) || !(camera.w > 0.0) || camera.z < -camera.w || camera.z > camera.w) continue;
        // Two directions along the surface.
        const glm::dvec3 n = sample.normal;
        const glm::dvec3 helper = std::abs(n.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec4 u(glm::normalize(glm::cross(n, helper)), 0.0);
        const glm::dvec4 v(glm::cross(n, glm::dvec3(u)), 0.0);
        // Map coordinates per unit along them (s = NDC / 2 + 1/2), and window pixels.
        const glm::dmat2 map = 0.5 * divideJacobian(light, lightViewProjection * u, lightViewProjection * v);
        const glm::dmat2 screen = glm::dmat2(0.5 * width, 0.0, 0.0, 0.5 * height) *
                                  divideJacobian(camera, cameraViewProjection * u, cameraViewProjection * v);
        // A surface edge-on to the light has no texels of its own (it is all one map line).
        if (!(std::abs(glm::determinant(map)) > kEdgeOnSine * glm::length(map[0]) * glm::length(map[1]))) continue;
        // The window step of a whole unit of s and of t along the surface: a texel of a map of
        // side res is 1 / res of it.
        const glm::dmat2 mapToScreen = screen * glm::inverse(map);
        needed = std::max(needed, std::max(glm::length(mapToScreen[0]), glm::length(mapToScreen[1])));
    }
    return needed * kMatchedSampleMargin;
}

std::vector<ReceiverSample> receiverSamples(const glm::dmat4& lightViewProjection, std::span<const engine::Aabb> receivers,
                                        int raysPerSide) {
    const glm::dmat4 toWorld = glm::inverse(lightViewProjection);
    const engine::Aabb reach = frustumBounds(lightViewProjection);
    std::vector<engine::Aabb> near;  // the receivers the light's frustum may reach
    for (const engine::Aabb& box : receivers)
        if (!reach.empty() && !glm::any(glm::greaterThan(glm::max(box.min, reach.min), glm::min(box.max, reach.max))))
            near.push_back(box);
    std::vector<ReceiverSample> points;
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
                int enteredAxis = -1;  // the face the ray came in by: its normal faces the light
                for (int axis = 0; axis < 3 && enter <= leave; ++axis) {
                    if (std::abs(direction[axis]) < 1e-300) {
                        if (from[axis] < box.min[axis] || from[axis] > box.max[axis]) enter = 2.0;
                        continue;
                    }
                    double t0 = (box.min[axis] - from[axis]) / direction[axis];
                    double t1 = (box.max[axis] - from[axis]) / direction[axis];
                    if (t0 > t1) std::swap(t0, t1);
                    if (t0 > enter) enter = t0, enteredAxis = axis;
                    leave = std::min(leave, t1);
                }
                // Starting inside the box (the light within it) enters by no face.
                if (enter > leave || enteredAxis < 0) continue;
                glm::dvec3 normal(0.0);
                normal[enteredAxis] = direction[enteredAxis] > 0.0 ? -1.0 : 1.0;
                points.push_back({from + direction * enter, normal});
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
