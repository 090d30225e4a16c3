#include "truth/TexelMetric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace truth {

namespace {

// The map's images of the surface's two tangent directions count as parallel (the surface
// edge-on to the light, the map Jacobian singular) below this sine of the angle between
// them. Tiny on purpose: a grazing but resolved surface has a large m, which is the
// aliasing the metric is there to show; only a numerically collapsed map is left out.
constexpr double kEdgeOnSine = 1e-9;

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// d(X/W, Y/W)/d(a, b) from the clip point c and its derivatives along the two tangent
// directions: d(X/W) = (dX - (X/W) dW) / W, so the perspective divide is differentiated
// exactly and an orthographic matrix (dW = 0) is just its special case.
glm::dmat2 divideJacobian(const glm::dvec4& c, const glm::dvec4& dA, const glm::dvec4& dB) {
    const glm::dvec2 ndc = glm::dvec2(c) / c.w;
    return glm::dmat2((glm::dvec2(dA) - ndc * dA.w) / c.w, (glm::dvec2(dB) - ndc * dB.w) / c.w);
}

} // namespace

double texelOnScreen(const glm::dvec3& point, const glm::dvec3& normal, const engine::FrameCamera& camera,
                     const glm::dmat4& mapViewProjection, int resolution) {
    // Any basis of the tangent plane gives the same m (it cancels in J_screen * J_map^-1);
    // the helper axis is the one least aligned with the normal, so the cross product is long.
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 helper = std::abs(n.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec4 u(glm::normalize(glm::cross(n, helper)), 0.0);
    const glm::dvec4 v(glm::cross(n, glm::dvec3(u)), 0.0);
    const glm::dvec4 p(point, 1.0);

    // The matrices are linear in homogeneous coordinates: the clip-space derivative along a
    // tangent direction is the matrix times that direction (w = 0).
    const glm::dvec4 light = mapViewProjection * p;
    const glm::dmat4 eyeClip = camera.projection * glm::inverse(camera.eyeToWorld);
    const glm::dvec4 eye = eyeClip * p;
    if (!(light.w > 0.0) || !(eye.w > 0.0)) return kNoValue;

    // Map coordinates (s, t) = NDC / 2 + 1/2; window pixels (x, y) = (NDC / 2 + 1/2) * size.
    const glm::dmat2 map = 0.5 * divideJacobian(light, mapViewProjection * u, mapViewProjection * v);
    const glm::dmat2 screen = glm::dmat2(0.5 * camera.width, 0.0, 0.0, 0.5 * camera.height) *
                              divideJacobian(eye, eyeClip * u, eyeClip * v);
    const double det = glm::determinant(map);
    if (!(std::abs(det) > kEdgeOnSine * glm::length(map[0]) * glm::length(map[1]))) return kNoValue;

    // Columns of J_screen * J_map^-1: the window displacement of a unit step of s and of t;
    // a texel's edges are those over the resolution.
    const glm::dmat2 texelToScreen = screen * glm::inverse(map);
    return std::max(glm::length(texelToScreen[0]), glm::length(texelToScreen[1])) / resolution;
}

int shadowLayerAt(const engine::ShadowView& view, const engine::FrameCamera& camera, const glm::dvec3& point) {
    if (!view.hasMap || view.layers.empty()) return -1;
    const int count = static_cast<int>(view.layers.size());
    int layer = 0;
    if (view.cube) {
        // Every face's L sits at the light; GL cube order +X, -X, +Y, -Y, +Z, -Z.
        const glm::dvec3 toPoint = point - glm::dvec3(view.layers[0].lightToWorld[3]);
        const glm::dvec3 size = glm::abs(toPoint);
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
        layer = 2 * axis + (toPoint[axis] < 0.0 ? 1 : 0);
    } else if (!view.cascadeSplits.empty()) {
        const double depth = -(glm::inverse(camera.eyeToWorld) * glm::dvec4(point, 1.0)).z;
        while (layer < count - 1 && depth > view.cascadeSplits[layer + 1]) ++layer;
    }
    return layer < count && view.layers[layer].rendered ? layer : -1;
}

} // namespace truth
