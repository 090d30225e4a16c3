// Light-space perspective shadow maps (math/LispsmWarp.h): the warped map holds the whole
// body (visible receivers and the casters over them), n follows the reference formula, the
// warp fades to the uniform map as the view turns parallel to the light, and texels near the
// camera shrink against the uniform fit of the same body.
#include "math/LispsmWarp.h"
#include "technique/UnseenShadows.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using engine::Aabb;
using shadowmap::fitLispsm;
using shadowmap::LightView;
using shadowmap::LispsmFit;
using shadowmap::WarpEye;

const Aabb kGround{{-500, -0.1, -500}, {500, 0, 500}};
const Aabb kPost{{-2.05, 0, -10.05}, {-1.95, 3, -9.95}};
const glm::dvec3 kSun = glm::normalize(glm::dvec3(0.3, -1.0, 0.4));

// A street camera: eye height 1.7, looking 6 degrees down the -z axis, 120 m deep.
engine::FrameCamera streetCamera(const glm::dvec3& direction = glm::dvec3(0.0, -0.1, -1.0)) {
    engine::FrameCamera camera;
    const glm::dvec3 eye(0.0, 1.7, 0.0);
    const glm::dvec3 up = std::abs(glm::normalize(direction).y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    camera.eyeToWorld = glm::inverse(glm::lookAt(eye, eye + direction, up));
    camera.projection = glm::perspective(0.9, 16.0 / 9.0, 0.1, 120.0);
    camera.width = 1280;
    camera.height = 720;
    return camera;
}

WarpEye eyeOf(const engine::FrameCamera& camera, double nearDepth = 0.1) {
    WarpEye eye;
    eye.position = camera.position();
    eye.direction = glm::normalize(-glm::dvec3(camera.eyeToWorld[2]));
    eye.nearDepth = nearDepth;
    return eye;
}

WarpEye streetEye() { return eyeOf(streetCamera()); }

// The body: the receivers' parts in the camera's view.
std::vector<glm::dvec3> bodyOf(const std::vector<Aabb>& receivers, const engine::FrameCamera& camera = streetCamera()) {
    return shadowmap::visibleReceiverPoints(receivers, camera);
}

// The window coordinates (s, t, depth) of a world point in the view's map, and its q.
glm::dvec4 mapCoordinates(const LightView& view, const glm::dvec3& world) {
    const glm::dvec4 clip = view.viewProjection() * glm::dvec4(world, 1.0);
    glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    const double depth = view.reversedZ ? ndc.z : 0.5 * ndc.z + 0.5;
    return {0.5 * ndc.x + 0.5, 0.5 * ndc.y + 0.5, depth, clip.w};
}

void expectInsideMap(const LightView& view, const glm::dvec3& world) {
    const glm::dvec4 p = mapCoordinates(view, world);
    EXPECT_GT(p.w, 0.0) << world.x << " " << world.y << " " << world.z;
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_GE(p[axis], 0.0) << "axis " << axis << " of " << world.x << " " << world.y << " " << world.z;
        EXPECT_LE(p[axis], 1.0) << "axis " << axis << " of " << world.x << " " << world.y << " " << world.z;
    }
}

TEST(LispsmWarp, HoldsEveryBodyPointAndTheCastersOverIt) {
    for (const bool reversed : {false, true}) {
        shadowmap::FrustumFitOptions options;
        options.reversedZ = reversed;
        const std::vector<glm::dvec3> body = bodyOf({kGround, kPost});
        const Aabb highCaster{{-1, 20, -31}, {1, 21, -29}};  // a roof far above the visible ground
        const std::vector<Aabb> casters{kPost, highCaster};
        LispsmFit fit;
        const LightView view = fitLispsm(kSun, streetEye(), body, casters, options, 1.0, &fit);
        ASSERT_TRUE(view.valid) << view.invalidReason;
        EXPECT_TRUE(view.warped);
        for (const glm::dvec3& p : body) expectInsideMap(view, p);
        for (int i = 0; i < 8; ++i) expectInsideMap(view, kPost.corner(i));
        // The roof hangs over the body (its shadow falls on visible ground): in the map too.
        for (int i = 0; i < 8; ++i) expectInsideMap(view, highCaster.corner(i));
        // Depth grows away from the light along a light ray: the post's top is nearer the light
        // than the ground under it.
        const glm::dvec3 top(-2.0, 3.0, -10.0);
        const glm::dvec3 under = top + kSun * (3.0 / -kSun.y);
        const double topDepth = mapCoordinates(view, top).z, groundDepth = mapCoordinates(view, under).z;
        if (reversed) EXPECT_GT(topDepth, groundDepth);
        else EXPECT_LT(topDepth, groundDepth);
        // ... and both land on the same texel: light rays stay parallel through the warp.
        EXPECT_NEAR(mapCoordinates(view, top).x, mapCoordinates(view, under).x, 1e-12);
        EXPECT_NEAR(mapCoordinates(view, top).y, mapCoordinates(view, under).y, 1e-12);
    }
}

TEST(LispsmWarp, NFollowsTheReferenceFormula) {
    // n = (z_n + sqrt(z_f z_n)) / sin(gamma), z_n = near / sin(gamma), z_f = z_n + d sin(gamma).
    const double nearDepth = 0.5, d = 100.0, s = 0.6;
    const double zn = nearDepth / s, zf = zn + d * s;
    EXPECT_NEAR(shadowmap::lispsmOptimalN(nearDepth, d, s), (zn + std::sqrt(zf * zn)) / s, 1e-12);

    // fitLispsm uses it, times lispsm_n_scale, where the warp has its full weight.
    const std::vector<glm::dvec3> body = bodyOf({kGround});
    for (const double scale : {1.0, 3.0}) {
        LispsmFit fit;
        fitLispsm(kSun, streetEye(), body, {}, {}, scale, &fit);
        ASSERT_EQ(fit.weight, 1.0);
        EXPECT_NEAR(fit.n, scale * shadowmap::lispsmOptimalN(0.1, fit.bodyDepth, fit.sinGamma), 1e-9 * fit.n);
        // The body's extent along the warp axis: the ground's along the view projected across
        // the light (at least its length along -z times the axis's share of it).
        EXPECT_GT(fit.bodyDepth, 90.0);
    }
}

TEST(LispsmWarp, ViewAlongTheLightGivesTheUniformMap) {
    const engine::FrameCamera down = streetCamera(kSun);
    const std::vector<glm::dvec3> body = bodyOf({kGround, kPost}, down);
    LispsmFit fit;
    const LightView warped = fitLispsm(kSun, eyeOf(down), body, std::vector<Aabb>{kPost}, {}, 1.0, &fit);
    EXPECT_EQ(fit.weight, 0.0);
    EXPECT_FALSE(warped.warped);
    // Uniform: an orthographic projection (no w from position) whose texels are the same
    // size everywhere.
    EXPECT_EQ(warped.projection[0][3], 0.0);
    EXPECT_EQ(warped.projection[1][3], 0.0);
    EXPECT_EQ(warped.projection[2][3], 0.0);
    EXPECT_EQ(warped.projection[3][3], 1.0);
    for (const glm::dvec3& p : body) expectInsideMap(warped, p);

    // Below the full-warp angle the weight falls smoothly (monotone, continuous) to 0 at the
    // uniform angle; n grows as 1/weight.
    double previous = 0.0;
    for (double degrees = 1.0; degrees <= 12.0; degrees += 0.25) {
        const double w = shadowmap::lispsmWarpWeight(std::sin(glm::radians(degrees)));
        EXPECT_GE(w, previous) << degrees;
        EXPECT_LE(w - previous, 0.06) << degrees;  // smoothstep over 8 degrees: at most 1.5/32 per 0.25 degree
        previous = w;
    }
    EXPECT_EQ(shadowmap::lispsmWarpWeight(std::sin(glm::radians(2.0))), 0.0);
    EXPECT_EQ(shadowmap::lispsmWarpWeight(std::sin(glm::radians(10.0))), 1.0);
}

// A texel's world extent at a ground point: the larger of the distances across which s and t
// change by one texel.
double texelAt(const LightView& view, const glm::dvec3& p, int resolution) {
    const double h = 1e-4;
    const glm::dvec4 a = mapCoordinates(view, p), bx = mapCoordinates(view, p + glm::dvec3(h, 0, 0)),
                     bz = mapCoordinates(view, p + glm::dvec3(0, 0, h));
    const glm::dvec2 ds(bx.x - a.x, bz.x - a.x), dt(bx.y - a.y, bz.y - a.y);
    // The Jacobian of (s, t) over the ground's (x, z); a texel is its inverse times 1/res.
    const double det = std::abs(ds.x * dt.y - ds.y * dt.x) / (h * h);
    const double sx = glm::length(glm::dvec2(dt.y, dt.x)) / h, sz = glm::length(glm::dvec2(ds.y, ds.x)) / h;
    return std::max(sx, sz) / (det * resolution);
}

TEST(LispsmWarp, TexelsShrinkNearTheCameraAndGrowFar) {
    const std::vector<glm::dvec3> body = bodyOf({kGround});
    const LightView warped = fitLispsm(kSun, streetEye(), body, {}, {}, 1.0);
    WarpEye along = streetEye();
    along.direction = kSun;  // the same body, fitted uniform
    const LightView uniform = fitLispsm(kSun, along, body, {}, {}, 1.0);
    const glm::dvec3 near(0.0, 0.0, -5.0), far(0.0, 0.0, -110.0);
    std::printf("texel near: %g warped, %g uniform; far: %g warped, %g uniform\n", texelAt(warped, near, 2048),
                texelAt(uniform, near, 2048), texelAt(warped, far, 2048), texelAt(uniform, far, 2048));
    // Measured: the near texel 8.9x smaller, the far one 1.5x larger; asserted with margin.
    EXPECT_LT(texelAt(warped, near, 2048), texelAt(uniform, near, 2048) / 4.0);
    EXPECT_GT(texelAt(warped, far, 2048), texelAt(uniform, far, 2048));
}

TEST(LispsmWarp, TexelsChangeSmoothlyAsTheViewTurnsAwayFromTheLight) {
    // Turning from along the light (uniform) through the fade (2..10 degrees) to a full warp,
    // in 0.1 degree steps: the texels at a near and a far body point change a little per step,
    // never at once (a margin swamping the warped x axis once made a 1% warp's map 80x
    // coarser across; a hard switch at the cutoff jumps by the whole warp).
    const glm::dvec3 axis = glm::normalize(glm::cross(kSun, glm::dvec3(0, 1, 0)));
    const glm::dvec3 eyePosition(0.0, 20.0, 10.0);
    // The body: a 60 x 80 m patch of ground ahead of the camera along the light.
    const glm::dvec3 centre = eyePosition + kSun * 35.0;
    std::vector<glm::dvec3> body;
    for (int i = 0; i < 8; ++i)
        body.push_back({centre.x + ((i & 1) ? 30.0 : -30.0), (i & 2) ? 0.0 : -0.1, centre.z + ((i & 4) ? 40.0 : -40.0)});
    const glm::dvec3 near(centre.x - 20.0, 0.0, centre.z - 30.0), far(centre.x + 20.0, 0.0, centre.z + 30.0);
    double previousNear = 0.0, previousFar = 0.0;
    for (int step = 10; step <= 120; ++step) {
        const double angle = glm::radians(0.1 * step);
        WarpEye eye;
        eye.position = eyePosition;
        eye.direction = kSun * std::cos(angle) + glm::cross(axis, kSun) * std::sin(angle);
        eye.nearDepth = 20.0;
        const LightView view = fitLispsm(kSun, eye, body, {}, {}, 1.0);
        const double texelNear = texelAt(view, near, 2048), texelFar = texelAt(view, far, 2048);
        if (step > 10) {
            EXPECT_NEAR(texelNear / previousNear, 1.0, 0.05) << 0.1 * step << " degrees";
            EXPECT_NEAR(texelFar / previousFar, 1.0, 0.05) << 0.1 * step << " degrees";
        }
        previousNear = texelNear;
        previousFar = texelFar;
    }
}

TEST(LispsmWarp, NormalOffsetTexelWidthsMatchTheMap) {
    // The lookup's texel width at the receiver, max(a q, b q^2) from NormalOffsetData, equals
    // the map's texel extent along the warp axis (b q^2) and across it (a q).
    const std::vector<glm::dvec3> body = bodyOf({kGround});
    const LightView view = fitLispsm(kSun, streetEye(), body, {}, {}, 1.0);
    ASSERT_TRUE(view.warped);
    // Probe along the frame's own axes (L's x: across; y: along the warp).
    const glm::dvec3 x(view.lightToWorld[0]), y(view.lightToWorld[1]);
    for (const glm::dvec3& p : {glm::dvec3(0, 0, -3), glm::dvec3(5, 0, -40), glm::dvec3(-20, 0, -100)}) {
        // Central differences: their error is O(h^2) relative to the curvature over q.
        const double q = mapCoordinates(view, p).w, h = 1e-3;
        const double ds = mapCoordinates(view, p + x * h).x - mapCoordinates(view, p - x * h).x;
        const double dt = mapCoordinates(view, p + y * h).y - mapCoordinates(view, p - y * h).y;
        const double across = 2.0 * h / std::abs(ds) / 2048.0, along = 2.0 * h / std::abs(dt) / 2048.0;
        const double n = view.nearPlane, f = view.farPlane;
        EXPECT_NEAR(across, q * 2.0 / (view.warpFitScale.x * 2048.0), 1e-6 * across);
        EXPECT_NEAR(along, q * q * (f - n) / (view.warpFitScale.y * f * n * 2048.0), 1e-5 * along);
    }
}

}  // namespace
