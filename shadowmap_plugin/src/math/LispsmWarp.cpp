#include "math/LispsmWarp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace shadowmap {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxWarpNearOverDepth = 256.0;

// The light frame: z toward the light, y the warp axis (the view direction with its part
// along the light removed), x = y cross z; with no warp axis, any axes across the light.
struct WarpFrame {
    glm::dvec3 x, y, z, origin;
    glm::dvec3 toLocal(const glm::dvec3& world) const {
        const glm::dvec3 d = world - origin;
        return {glm::dot(x, d), glm::dot(y, d), glm::dot(z, d)};
    }
};

// The warp W (rows x, y, z, w) acting on coordinates relative to C: x, z divided by the
// distance along y, y mapped from [n, f] to [-1, 1]. Uniform (n infinite): the identity.
glm::dmat4 warpMatrix(double n, double f) {
    glm::dmat4 w(1.0);
    if (!std::isfinite(n)) return w;
    w[1][1] = (f + n) / (f - n);
    w[3][1] = -2.0 * f * n / (f - n);
    w[1][3] = 1.0;
    w[3][3] = 0.0;
    return w;
}

}  // namespace

double lispsmWarpWeight(double sinGamma) {
    const double gamma = std::asin(std::clamp(sinGamma, 0.0, 1.0));
    const double t = std::clamp((gamma - kLispsmUniformAngle) / (kLispsmFullWarpAngle - kLispsmUniformAngle), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

double lispsmOptimalN(double nearDepth, double bodyDepth, double sinGamma) {
    const double zn = nearDepth / sinGamma;
    const double zf = zn + bodyDepth * sinGamma;
    return (zn + std::sqrt(zf * zn)) / sinGamma;
}

LightView fitLispsm(const glm::dvec3& direction, const WarpEye& eye, std::span<const glm::dvec3> body,
                    std::span<const engine::Aabb> casters, const FrustumFitOptions& options, double nScale,
                    LispsmFit* chosen) {
    LightView v;
    v.reversedZ = options.reversedZ;
    WarpFrame frame;
    frame.z = -glm::normalize(direction);
    const glm::dvec3 across = eye.direction - glm::dot(eye.direction, frame.z) * frame.z;
    LispsmFit fit;
    fit.sinGamma = std::min(glm::length(across), 1.0);
    fit.weight = lispsmWarpWeight(fit.sinGamma);
    // The map turns with the view about the light's axis while the view's projection across
    // the light is defined at all, warped or not, so fading the warp out moves no texel at
    // once; only a view exactly along the light (within double's reach) takes any axis.
    if (fit.sinGamma > 1e-9) {
        frame.y = across / glm::length(across);
    } else {
        const glm::dmat4 any = lightToWorldFromDirection(glm::dvec3(0.0), direction);
        frame.y = glm::dvec3(any[1]);
    }
    frame.x = glm::cross(frame.y, frame.z);
    frame.origin = eye.position;

    // The body in the frame, and its rectangle across the light.
    std::vector<glm::dvec3> points;
    for (const glm::dvec3& p : body)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) points.push_back(frame.toLocal(p));
    v.empty = points.empty();
    if (v.empty) {  // nothing to hold: a unit placeholder, its pass skipped
        v.lightToWorld = lightToWorldFromDirection(eye.position, direction);
        v.nearPlane = 0.0;
        v.farPlane = 1.0;
        v.projection = glm::orthoRH_NO(-0.5, 0.5, -0.5, 0.5, 0.0, 1.0);
        v.valid = true;
        if (chosen) *chosen = fit;
        return v;
    }
    engine::Aabb r;
    for (const glm::dvec3& p : points) r.extend(p);
    // Casters over the rectangle reach toward the light: extrude the body up to them.
    double zTop = r.max.z;
    for (const engine::Aabb& box : casters) {
        if (!usableBounds(box)) continue;
        engine::Aabb c;
        for (int i = 0; i < 8; ++i) c.extend(frame.toLocal(box.corner(i)));
        const bool overlaps = c.min.x <= r.max.x && c.max.x >= r.min.x && c.min.y <= r.max.y && c.max.y >= r.min.y;
        if (overlaps && c.max.z > r.min.z) zTop = std::max(zTop, c.max.z);
    }
    const std::size_t bodyPoints = points.size();
    for (std::size_t i = 0; i < bodyPoints; ++i) points.push_back({points[i].x, points[i].y, zTop});

    // The perspective along y: its centre n before the body's near end, across the light at
    // the eye (x = 0 in this frame), and along the light level with the body's lowest point.
    // Any level gives the same map, but not the same depth, z' = (z - z_C) / q: a horizontal
    // receiver's depth then slopes across the map by (z - z_C) d(1/q), and the slope-scaled
    // polygon offset grows with it. Measured on the outdoor street (640x360, 2048 maps,
    // error / acne %): at the eye's level one map 0.168 / 0.109, 2 cascades 0.263 / 0.218;
    // at the lowest point 0.168 / 0.109 and 0.143 / 0.098; halfway up the body 0.380 and
    // 0.504 (leak: shadows detached); a body's height above it 1.46 and 1.87.
    fit.bodyDepth = r.max.y - r.min.y;
    const double nearDepth = std::max(eye.nearDepth, 1e-9 * std::max(fit.bodyDepth, 1e-300));
    fit.n = kInf;
    if (fit.weight > 0.0 && fit.bodyDepth > 0.0) {
        fit.n = nScale * lispsmOptimalN(nearDepth, fit.bodyDepth, fit.sinGamma) / fit.weight;
        // A warp this weak changes texel sizes by under 1/kMaxWarpNearOverDepth across the
        // map, while its texgen rows, cast to float for the GPU, cancel to about n/d float
        // steps (t = a + b/q with a, b ~ n/d): at 256 that is 0.06 of a texel at 2048, more
        // beyond. So past it the map is the uniform one.
        if (!(fit.n <= kMaxWarpNearOverDepth * fit.bodyDepth)) fit.n = kInf;
    }
    const double yCentre = std::isfinite(fit.n) ? r.min.y - fit.n : 0.0;
    const double zCentre = r.min.z;
    const double n = fit.n, f = fit.n + fit.bodyDepth;
    const glm::dmat4 warp = warpMatrix(n, f);

    // The warped body's box: x, y, z after the perspective divide.
    engine::Aabb warped;
    for (const glm::dvec3& p : points) {
        const glm::dvec4 h = warp * glm::dvec4(p.x, p.y - yCentre, p.z - zCentre, 1.0);
        warped.extend(glm::dvec3(h) / h.w);
    }
    // Margins per axis: after the divide the axes have unrelated scales (x' and z' shrink as
    // 1/n while y' spans [-1, 1]), so one margin from the largest would swamp the others (a
    // weak warp's body then filled a hundredth of the map across). An axis of no extent gets
    // a margin relative to its position.
    const glm::dvec3 size = warped.max - warped.min;
    const auto margin = [](double extent, double fraction, double position) {
        const double pad = fraction * extent;
        return pad > 0.0 ? pad : 1e-6 * std::max(std::abs(position), 1e-300);
    };
    const glm::dvec3 pad(margin(size.x, options.extentMargin, warped.max.x),
                         margin(size.y, options.extentMargin, warped.max.y),
                         margin(size.z, std::max(options.depthMargin, options.extentMargin), warped.max.z));
    const glm::dvec3 lo = warped.min - pad, hi = warped.max + pad;

    // O: the orthographic fit, looking down -z (the light's direction) with depth 0 (1 with
    // reversed Z) at the top, toward the light.
    glm::dmat4 ortho(1.0);
    ortho[0][0] = 2.0 / (hi.x - lo.x);
    ortho[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    ortho[1][1] = 2.0 / (hi.y - lo.y);
    ortho[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    const double depth = hi.z - lo.z;
    if (options.reversedZ) {
        ortho[2][2] = 1.0 / depth;
        ortho[3][2] = -lo.z / depth;
    } else {
        ortho[2][2] = -2.0 / depth;
        ortho[3][2] = (hi.z + lo.z) / depth;
    }

    const glm::dvec3 centre = frame.origin + frame.y * yCentre + frame.z * zCentre;
    v.lightToWorld = glm::dmat4(glm::dvec4(frame.x, 0.0), glm::dvec4(frame.y, 0.0), glm::dvec4(frame.z, 0.0),
                                glm::dvec4(centre, 1.0));
    v.projection = ortho * warp;
    v.warped = std::isfinite(n);
    v.warpFitScale = {ortho[0][0], ortho[1][1]};
    // Near and far along the warp axis; a uniform map's are those of its depth, as for
    // fitDirectionalLight.
    v.nearPlane = v.warped ? n : 0.0;
    v.farPlane = v.warped ? f : depth;
    v.nearestReceiver = v.nearPlane;
    v.valid = isFiniteMatrix(v.lightToWorld) && isFiniteMatrix(v.projection) && depth > 0.0;
    if (!v.valid) v.invalidReason = "fitted light-space perspective frustum is degenerate";
    if (chosen) *chosen = fit;
    return v;
}

}  // namespace shadowmap
