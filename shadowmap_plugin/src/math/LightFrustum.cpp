#include "math/LightFrustum.h"

#include "engine/scene/FrustumCull.h"
#include "engine/util/FormatNumber.h"
#include "math/Texgen.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace shadowmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

bool usable(const engine::Aabb& box) {
    return !box.empty() && isFinite(box.min) && isFinite(box.max);
}

bool contains(const engine::Aabb& box, const glm::dvec3& p) {
    return glm::all(glm::lessThanEqual(box.min, p)) && glm::all(glm::lessThanEqual(p, box.max));
}

// The light's rotation columns and position, for exact light-relative transforms:
// p_light = R^T * (p_world - position), subtracting first so 10^7-sized coordinates cancel.
struct RigidFrame {
    glm::dvec3 x, y, z, origin;
    explicit RigidFrame(const glm::dmat4& L) : x(L[0]), y(L[1]), z(L[2]), origin(L[3]) {}
    glm::dvec3 toLocal(const glm::dvec3& world) const {
        const glm::dvec3 d = world - origin;
        return {glm::dot(x, d), glm::dot(y, d), glm::dot(z, d)};
    }
    std::array<glm::dvec3, 8> corners(const engine::Aabb& box) const {
        std::array<glm::dvec3, 8> out;
        for (int i = 0; i < 8; ++i) out[i] = toLocal(box.corner(i));
        return out;
    }
};

// Depth range (distance along -Z) of a box, given by its corners in a light frame, clipped
// to the square pyramid |x| <= k*d, |y| <= k*d, d = -z, apex at the light. Clipping each
// of the six faces yields every vertex of box ∩ pyramid except the apex; when the box holds
// the apex (apexInside), depth 0 is reached too (the near clamp then takes over).
// Returns false when nothing is inside.
bool pyramidDepthRange(const std::array<glm::dvec3, 8>& c, double k, bool apexInside, double& dmin,
                       double& dmax) {
    static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    // Inside when dot(n, p) >= 0.
    const glm::dvec3 planes[4] = {{-1, 0, -k}, {1, 0, -k}, {0, -1, -k}, {0, 1, -k}};
    // A box wholly outside one plane has nothing inside (the common case for a narrow light
    // among many boxes): no clipping needed.
    if (!apexInside)
        for (const glm::dvec3& plane : planes)
            if (std::all_of(c.begin(), c.end(), [&](const glm::dvec3& p) { return glm::dot(plane, p) < 0.0; })) {
                dmin = kInf;
                dmax = -kInf;
                return false;
            }
    bool any = apexInside;
    dmin = apexInside ? 0.0 : kInf;
    dmax = apexInside ? 0.0 : -kInf;
    for (const auto& face : kFaces) {
        // A quad clipped by four planes has at most 8 vertices.
        std::array<glm::dvec3, 12> poly, next;
        int n = 4;
        for (int i = 0; i < 4; ++i) poly[i] = c[face[i]];
        for (const glm::dvec3& plane : planes) {
            int m = 0;
            for (int i = 0; i < n; ++i) {
                const glm::dvec3& prev = poly[(i + n - 1) % n];
                const glm::dvec3& cur = poly[i];
                const double dp = glm::dot(plane, prev), dc = glm::dot(plane, cur);
                if ((dp >= 0.0) != (dc >= 0.0)) {
                    const double t = dp / (dp - dc);
                    next[m++] = prev + t * (cur - prev);
                }
                if (dc >= 0.0) next[m++] = cur;
            }
            n = m;
            poly = next;
            if (n == 0) break;
        }
        for (int i = 0; i < n; ++i) {
            const double d = -poly[i].z;
            dmin = std::min(dmin, d);
            dmax = std::max(dmax, d);
            any = true;
        }
    }
    return any;
}

std::string describe(const char* what, const glm::dvec3& v) {
    return std::string(what) + " (" + engine::formatNumber(v.x) + ", " + engine::formatNumber(v.y) + ", " +
           engine::formatNumber(v.z) + ")";
}

}  // namespace

std::string directionProblem(const engine::LightInstance& instance, glm::dvec3& direction) {
    direction = -glm::dvec3(instance.world[2]);
    if (!isFinite(direction)) return describe("light direction is not finite", direction);
    const double len = glm::length(direction);
    if (!(len > 1e-12)) return describe("light direction has zero length", direction);
    direction /= len;
    return {};
}

LightView invalidView(std::string reason) {
    LightView v;
    v.valid = false;
    v.invalidReason = std::move(reason);
    return v;
}

bool isFiniteMatrix(const glm::dmat4& m) { return isFinite(m); }
bool usableBounds(const engine::Aabb& box) { return usable(box); }

namespace {

// Final guard: a view is only valid when everything in it is a finite, usable number
// (the far plane may be +infinity: the projection's numbers stay finite then).
void checkFinite(LightView& v) {
    if (isFinite(v.lightToWorld) && isFinite(v.projection) && std::isfinite(v.nearPlane) &&
        v.nearPlane >= 0.0 && (std::isfinite(v.farPlane) || v.farPlane > 0.0) &&
        v.farPlane > v.nearPlane) {
        v.valid = true;
        return;
    }
    v.valid = false;
    v.invalidReason = "fitted light frustum is degenerate (near " + engine::formatNumber(v.nearPlane) + ", far " +
                      engine::formatNumber(v.farPlane) + ")";
}

// Perspective near/far from receiver and caster depth ranges. Returns false when no
// receiver lies in front of the light (and within range).
struct DepthFit {
    double receiverMin = kInf, receiverMax = -kInf;
    std::vector<double> casterMins;  // nearest depth of each caster inside the frustum
    bool anyReceiver() const { return receiverMax >= receiverMin; }
};

void finishPerspectiveDepth(const DepthFit& fit, double range, const FrustumFitOptions& opt,
                            bool& empty, double& nearPlane, double& farPlane) {
    const bool ranged = range > 0.0 && std::isfinite(range);
    empty = !fit.anyReceiver() || (ranged && fit.receiverMin >= range);
    if (empty) {  // placeholder numbers: the pass is skipped
        farPlane = ranged ? range : 1.0;
        nearPlane = farPlane * 1e-3;
        return;
    }
    double farD = fit.receiverMax;
    if (ranged) farD = std::min(farD, range);
    double nearD = fit.receiverMin;
    for (double c : fit.casterMins)
        if (c < farD) nearD = std::min(nearD, c);
    farD *= 1.0 + opt.depthMargin;
    nearD *= 1.0 - opt.depthMargin;
    nearPlane = std::max(nearD, farD * opt.minNearFraction);
    farPlane = farD;
    // Forced planes (near_plane / far_plane settings) replace the fitted ones; a near beyond
    // the far makes the view degenerate (checkFinite), so the light loses its shadow loudly.
    if (opt.nearPlane > 0.0) nearPlane = opt.nearPlane;
    if (opt.farPlane > 0.0) farPlane = opt.farPlane;
    // Reversed Z without a forced far: infinite. Depth is then n/d, whose float error is
    // relative everywhere; a finite far drives depth to 0 near it, where the lookup's
    // absolute errors outgrow float polygon-offset units (measured: 6% acne on a point
    // light's receivers near its fitted far, tools/shadowmap-stress light_on_surface).
    else if (opt.reversedZ) farPlane = std::numeric_limits<double>::infinity();
}

// Aspect 1. farPlane may be +infinity. Not GLM's helpers: the conventions are explicit here,
// whatever GLM_FORCE_* says, and the reversed ones are written so the depth row keeps its
// relative precision (no 1 - n/d cancellation).
glm::dmat4 perspective(double fovy, double nearPlane, double farPlane, bool reversedZ) {
    const double n = nearPlane, f = farPlane, cot = 1.0 / std::tan(0.5 * fovy);
    glm::dmat4 p(0.0);
    p[0][0] = cot;
    p[1][1] = cot;
    p[2][3] = -1.0;  // w_clip = -z_eye = d
    if (!reversedZ && std::isinf(f)) {  // z_ndc = 1 - 2n/d
        p[2][2] = -1.0;
        p[3][2] = -2.0 * n;
    } else if (!reversedZ) {  // z_ndc in [-1, 1]: glm::perspectiveRH_NO
        p[2][2] = -(f + n) / (f - n);
        p[3][2] = -2.0 * f * n / (f - n);
    } else if (std::isinf(f)) {  // z_ndc = n/d: 1 at near, 0 at infinity
        p[2][2] = 0.0;
        p[3][2] = n;
    } else {  // z_ndc = n (f - d) / ((f - n) d): 1 at near, 0 at far
        p[2][2] = n / (f - n);
        p[3][2] = n * f / (f - n);
    }
    return p;
}

// Orthographic depth rows: NO maps d = near..far to -1..1; reversed to 1..0.
glm::dmat4 orthographic(double hx, double hy, double nearPlane, double farPlane, bool reversedZ) {
    glm::dmat4 p = glm::orthoRH_NO(-hx, hx, -hy, hy, nearPlane, farPlane);
    if (reversedZ) {  // z_ndc = (far - d) / (far - near), d = -z_eye
        p[2][2] = 1.0 / (farPlane - nearPlane);
        p[3][2] = farPlane / (farPlane - nearPlane);
    }
    return p;
}

}  // namespace

ShadowBounds ShadowBounds::fromScene(const engine::Scene& scene) {
    ShadowBounds b;
    for (const engine::MeshInstance& mi : scene.meshInstances) {
        if (mi.castShadows) b.casters.push_back(mi.worldBounds);
        if (mi.receiveShadows) b.receivers.push_back(mi.worldBounds);
    }
    return b;
}

glm::dmat4 LightView::worldToLight() const {
    // L is rigid: L^-1 = [R^T | -R^T p].
    const RigidFrame f(lightToWorld);
    glm::dmat4 inv(1.0);
    for (int i = 0; i < 3; ++i) {
        inv[i][0] = f.x[i];
        inv[i][1] = f.y[i];
        inv[i][2] = f.z[i];
    }
    inv[3] = glm::dvec4(-glm::dot(f.x, f.origin), -glm::dot(f.y, f.origin),
                        -glm::dot(f.z, f.origin), 1.0);
    return inv;
}

glm::dmat4 LightView::viewProjection() const {
    return projection * worldToLight();
}

glm::dmat4 LightView::texgenPlanes() const {
    return (reversedZ ? scaleBiasZeroToOne() : scaleBias()) * viewProjection();
}

double windowDepthPerTexel(const LightView& view, int resolution) {
    // P[0][0] = 1 / half width (orthographic) or cot(half angle) (perspective).
    const double n = view.nearPlane, f = view.farPlane;
    if (view.warped) {
        // P = O * W (LispsmWarp.h): at distance q along the warp axis a texel is
        // 2 q / (O00 res) wide across it and q^2 (f - n) / (O11 f n res) along it, and window
        // depth changes by |O22| / q per unit toward the light (half that in [-1, 1] clip).
        const double o00 = view.warpFitScale.x, o11 = view.warpFitScale.y;
        const double o22 = std::abs(view.projection[2][2]);
        const double width = std::max(2.0 / o00, (f - n) / (o11 * f));  // texel width / (q / res) at q = n
        return width * o22 * (view.reversedZ ? 1.0 : 0.5) / resolution;
    }
    const double texelPerDistance = 2.0 / (view.projection[0][0] * resolution);
    if (view.projection[2][3] == 0.0) return texelPerDistance / (f - n);  // orthographic
    const double d = std::max(view.nearestReceiver, n);
    const double depthSlope = std::isinf(f) ? n / (d * d) : n * f / ((f - n) * d * d);
    return texelPerDistance * d * depthSlope;
}

glm::dvec3 cubeFaceDirection(int face) {
    static const glm::dvec3 dirs[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    return dirs[face];
}

glm::dvec3 cubeFaceUp(int face) {
    // OpenGL 4.5 table 8.19 (sc, tc per major axis) rendered with window y = t.
    static const glm::dvec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                      {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return ups[face];
}

double cubeShadowReferenceDepth(const glm::dvec3& v, double n, double f, bool reversedZ) {
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (std::isinf(f)) return reversedZ ? n / m : 1.0 - n / m;
    if (reversedZ) return n * (f - m) / ((f - n) * m);
    const double zNdc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * m);
    return 0.5 * zNdc + 0.5;
}

glm::dmat4 lightToWorldFromDirection(const glm::dvec3& position, const glm::dvec3& direction) {
    const glm::dvec3 forward = glm::normalize(direction);
    // The world axis least parallel to the direction (Y preferred on ties): never degenerate.
    const glm::dvec3 axes[3] = {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
    glm::dvec3 up = axes[0];
    double best = kInf;
    for (const glm::dvec3& a : axes) {
        const double d = std::abs(glm::dot(a, forward));
        if (d < best) {
            best = d;
            up = a;
        }
    }
    const glm::dvec3 x = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 y = glm::cross(x, forward);
    const glm::dvec3 z = -forward;
    return glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0), glm::dvec4(z, 0.0),
                      glm::dvec4(position, 1.0));
}

LightView fitSpotLight(const engine::LightInstance& instance, const engine::Light& light,
                       const ShadowBounds& bounds, const FrustumFitOptions& opt) {
    const glm::dvec3 position = instance.position();
    if (!isFinite(position))
        return invalidView(describe("spot light position is not finite", position));
    glm::dvec3 direction;
    if (std::string why = directionProblem(instance, direction); !why.empty())
        return invalidView("spot " + why);
    if (!(light.outerConeAngle > 0.0) || !std::isfinite(light.outerConeAngle))
        return invalidView("spot light outer cone angle must be a positive number");

    LightView v;
    v.reversedZ = opt.reversedZ;
    const double half = std::min(light.outerConeAngle, opt.maxSpotHalfAngle);
    if (light.outerConeAngle > opt.maxSpotHalfAngle) {
        v.clampWarning = "spot outer cone angle " + engine::formatNumber(light.outerConeAngle * 57.29577951308232) +
                         " deg clamped to " + engine::formatNumber(opt.maxSpotHalfAngle * 57.29577951308232) +
                         " deg for its shadow map (a perspective map needs < 90 deg)";
    }
    const double k = std::tan(half);
    v.lightToWorld = lightToWorldFromDirection(position, direction);
    const RigidFrame frame(v.lightToWorld);

    DepthFit fit;
    double dmin, dmax;
    for (const engine::Aabb& box : bounds.receivers) {
        if (!usable(box) ||
            !pyramidDepthRange(frame.corners(box), k, contains(box, position), dmin, dmax))
            continue;
        fit.receiverMin = std::min(fit.receiverMin, dmin);
        fit.receiverMax = std::max(fit.receiverMax, dmax);
    }
    for (const engine::Aabb& box : bounds.casters)
        if (usable(box) &&
            pyramidDepthRange(frame.corners(box), k, contains(box, position), dmin, dmax))
            fit.casterMins.push_back(dmin);

    finishPerspectiveDepth(fit, light.range, opt, v.empty, v.nearPlane, v.farPlane);
    v.nearestReceiver = fit.anyReceiver() ? fit.receiverMin : 0.0;
    v.projection = perspective(2.0 * half, v.nearPlane, v.farPlane, v.reversedZ);
    checkFinite(v);
    return v;
}

LightView fitDirectionalLight(const engine::LightInstance& instance, const engine::Light& light,
                              const ShadowBounds& bounds, const FrustumFitOptions& opt) {
    glm::dvec3 direction;
    if (std::string why = directionProblem(instance, direction); !why.empty())
        return invalidView("directional " + why);

    // Anchor the light frame at the receivers' centre: numbers relative to the scene.
    engine::Aabb all;
    for (const engine::Aabb& box : bounds.receivers)
        if (usable(box)) all.extend(box);
    LightView v;
    v.reversedZ = opt.reversedZ;
    v.empty = all.empty();
    if (v.empty) {  // placeholder: a unit box at the casters (or the origin); pass skipped
        engine::Aabb casters;
        for (const engine::Aabb& box : bounds.casters)
            if (usable(box)) casters.extend(box);
        const glm::dvec3 at = casters.empty() ? glm::dvec3(0.0) : casters.center();
        v.lightToWorld = lightToWorldFromDirection(at, direction);
        v.nearPlane = 0.0;
        v.farPlane = 1.0;
        v.projection = orthographic(0.5, 0.5, 0.0, 1.0, v.reversedZ);
        checkFinite(v);
        return v;
    }
    const RigidFrame frame(lightToWorldFromDirection(all.center(), direction));

    engine::Aabb r;  // receivers in the light frame (z toward the light)
    for (const engine::Aabb& box : bounds.receivers) {
        if (!usable(box)) continue;
        for (const glm::dvec3& p : frame.corners(box)) r.extend(p);
    }
    double zTop = r.max.z;
    for (const engine::Aabb& box : bounds.casters) {
        if (!usable(box)) continue;
        engine::Aabb c;
        for (const glm::dvec3& p : frame.corners(box)) c.extend(p);
        const bool overlapsXY =
            c.min.x <= r.max.x && c.max.x >= r.min.x && c.min.y <= r.max.y && c.max.y >= r.min.y;
        // Anything of it nearer the light than the farthest receiver can shadow one.
        if (overlapsXY && c.max.z > r.min.z) zTop = std::max(zTop, c.max.z);
    }
    const double wx = r.max.x - r.min.x, wy = r.max.y - r.min.y, wz = zTop - r.min.z;
    double pad = opt.extentMargin * std::max({wx, wy, wz});
    if (!(pad > 0.0)) pad = 1e-6;  // a single point: still a usable box
    const double padZ = std::max(opt.depthMargin * wz, pad);
    const double hx = 0.5 * wx + pad, hy = 0.5 * wy + pad;

    const glm::dvec3 eyeLocal(0.5 * (r.min.x + r.max.x), 0.5 * (r.min.y + r.max.y), zTop + padZ);
    const glm::dvec3 eye =
        frame.origin + frame.x * eyeLocal.x + frame.y * eyeLocal.y + frame.z * eyeLocal.z;
    v.lightToWorld = glm::dmat4(glm::dvec4(frame.x, 0.0), glm::dvec4(frame.y, 0.0),
                                glm::dvec4(frame.z, 0.0), glm::dvec4(eye, 1.0));
    v.nearPlane = 0.0;
    v.farPlane = wz + 2.0 * padZ;
    v.projection = orthographic(hx, hy, v.nearPlane, v.farPlane, v.reversedZ);
    checkFinite(v);
    return v;
}

LightView orthographicViewOfBox(const glm::dmat4& frame, const glm::dvec2& centre, const glm::dvec2& half,
                                double zBottom, double zTop, bool reversedZ) {
    const RigidFrame f(frame);
    LightView v;
    v.reversedZ = reversedZ;
    v.empty = false;
    v.lightToWorld = glm::dmat4(glm::dvec4(f.x, 0.0), glm::dvec4(f.y, 0.0), glm::dvec4(f.z, 0.0),
                                glm::dvec4(f.origin + f.x * centre.x + f.y * centre.y + f.z * zTop, 1.0));
    v.nearPlane = 0.0;
    v.farPlane = zTop - zBottom;
    v.projection = orthographic(half.x, half.y, v.nearPlane, v.farPlane, reversedZ);
    checkFinite(v);
    return v;
}

PointLightViews fitPointLight(const engine::LightInstance& instance, const engine::Light& light,
                              const ShadowBounds& bounds, const FrustumFitOptions& opt) {
    PointLightViews out;
    const glm::dvec3 position = instance.position();
    if (!isFinite(position)) {
        out.invalidReason = describe("point light position is not finite", position);
        for (LightView& f : out.faces) f = invalidView(out.invalidReason);
        return out;
    }

    DepthFit fit;
    double dmin, dmax;
    std::array<bool, 6> seesReceiver{};
    for (int face = 0; face < engine::kCubeFaces; ++face) {
        const glm::dvec3 dir = cubeFaceDirection(face), up = cubeFaceUp(face);
        const glm::dvec3 x = glm::cross(dir, up);  // right: the face's +s direction
        out.faces[face].lightToWorld = glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(up, 0.0),
                                                  glm::dvec4(-dir, 0.0), glm::dvec4(position, 1.0));
        const RigidFrame frame(out.faces[face].lightToWorld);
        for (const engine::Aabb& box : bounds.receivers) {
            if (!usable(box) ||
                !pyramidDepthRange(frame.corners(box), 1.0, contains(box, position), dmin, dmax))
                continue;
            if (!(light.range > 0.0) || dmin < light.range) seesReceiver[face] = true;
            fit.receiverMin = std::min(fit.receiverMin, dmin);
            fit.receiverMax = std::max(fit.receiverMax, dmax);
        }
        for (const engine::Aabb& box : bounds.casters)
            if (usable(box) &&
                pyramidDepthRange(frame.corners(box), 1.0, contains(box, position), dmin, dmax))
                fit.casterMins.push_back(dmin);
    }

    bool empty = false;
    finishPerspectiveDepth(fit, light.range, opt, empty, out.nearPlane, out.farPlane);
    out.reversedZ = opt.reversedZ;
    const glm::dmat4 projection =
        perspective(glm::half_pi<double>(), out.nearPlane, out.farPlane, out.reversedZ);
    out.valid = true;
    for (int face = 0; face < engine::kCubeFaces; ++face) {
        LightView& f = out.faces[face];
        f.reversedZ = out.reversedZ;
        f.nearestReceiver = fit.anyReceiver() ? fit.receiverMin : 0.0;
        f.projection = projection;
        f.nearPlane = out.nearPlane;
        f.farPlane = out.farPlane;
        f.empty = empty || !seesReceiver[face];
        checkFinite(f);
        if (!f.valid && out.valid) {
            out.valid = false;
            out.invalidReason = f.invalidReason;
        }
    }
    return out;
}

bool PointLightViews::faceSeesBox(int face, const engine::Aabb& worldBox) const {
    if (!valid || face < 0 || face >= engine::kCubeFaces) return false;
    return engine::boxIntersectsFrustum(faces[face].viewProjection(), worldBox);
}

}  // namespace shadowmap
