// The on-screen texel size m (truth/TexelMetric.h) against values computed by hand, and the
// layer a pixel's texel comes from. No GL: cameras and light maps are matrices built here.
#include "truth/TexelMetric.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

constexpr double kRelative = 1e-9;  // double arithmetic on a few 4x4 products
constexpr int kWidth = 1280, kHeight = 720;
const double kFov = glm::radians(60.0);  // the camera's vertical field of view

// A perspective camera at `eye` looking at `target`, square pixels.
engine::FrameCamera cameraAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    engine::FrameCamera camera;
    camera.eyeToWorld = glm::inverse(glm::lookAt(eye, target, up));
    camera.projection = glm::perspective(kFov, double(kWidth) / kHeight, 0.1, 100.0);
    camera.width = kWidth;
    camera.height = kHeight;
    return camera;
}

// An orthographic light 10 above the ground y = 0 looking straight down, its map spanning
// world x in [-halfX, halfX] (s) and z in [-halfZ, halfZ] (t): P_light * L^-1.
glm::dmat4 sunStraightDown(double halfX, double halfZ) {
    return glm::ortho(-halfX, halfX, -halfZ, halfZ, 0.1, 100.0) *
           glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0), glm::dvec3(0, 0, -1));
}

void expectRelative(double actual, double expected) {
    EXPECT_NEAR(actual, expected, kRelative * expected) << "relative error " << actual / expected - 1.0;
}

} // namespace

// Light and camera both straight down onto y = 0, the camera at height h: a texel is 2H/R
// wide on the ground, a pixel 2 h tan(f/2) / Hpx, and the ground is parallel to both image
// planes, so m = (2H/R) / (2 h tan(f/2) / Hpx) at every point, not only under the camera.
TEST(TexelMetric, MatchesTheHandComputedValueOnAPlaneSeenStraightDown) {
    constexpr double kHalf = 8.0, kHeightAbove = 10.0;
    constexpr int kResolution = 1024;
    const engine::FrameCamera camera = cameraAt({0, kHeightAbove, 0}, {0, 0, 0}, {0, 0, -1});
    const double texel = 2.0 * kHalf / kResolution;
    const double pixel = 2.0 * kHeightAbove * std::tan(kFov / 2) / kHeight;
    for (const glm::dvec3 point : {glm::dvec3(0, 0, 0), glm::dvec3(3.5, 0, -2.0), glm::dvec3(-6.0, 0, 4.0)})
        expectRelative(truth::texelOnScreen(point, {0, 1, 0}, camera, sunStraightDown(kHalf, kHalf), kResolution),
                       texel / pixel);
}

// The same sun with texels 4x longer along z (map half-widths 4 in x, 16 in z), seen by a
// camera 10 away at 45 degrees above the ground in the y-z plane, looking at the origin
// (the image centre). There a pixel spans s = 2 * 10 * tan(30deg) / 720 across the view ray;
// the camera's x is world x, so a step along x is unforeshortened (x texel: 8/R / s pixels),
// while a step along z leaves the ray at 45 degrees: only sin 45 of it shows (z texel:
// 32/R * sin 45 / s pixels = 2.83 times the x texel). m is the z edge.
TEST(TexelMetric, ForeshortensTheEdgeAlongATiltedView) {
    constexpr double kDistance = 10.0, kHalfX = 4.0, kHalfZ = 16.0;
    constexpr int kResolution = 2048;
    const double diagonal = std::sqrt(0.5);  // sin 45 = cos 45
    const engine::FrameCamera camera =
        cameraAt(kDistance * glm::dvec3(0, diagonal, diagonal), {0, 0, 0}, {0, 1, 0});
    const double pixel = 2.0 * kDistance * std::tan(kFov / 2) / kHeight;
    expectRelative(truth::texelOnScreen({0, 0, 0}, {0, 1, 0}, camera, sunStraightDown(kHalfX, kHalfZ), kResolution),
                   2.0 * kHalfZ / kResolution * diagonal / pixel);
}

// A spot light at the camera, looking where it looks, with the camera's vertical field of
// view: its map is the camera's image cut to a square, so a texel is Hpx / R pixels on every
// edge, whatever the surface's slope and wherever the point lies in the view. Off the view's
// centre on a slanted surface both perspective divides move (dW != 0): this checks them.
TEST(TexelMetric, ASpotLightAtTheCameraGivesHeightOverResolutionEverywhere) {
    constexpr int kResolution = 512;
    const engine::FrameCamera camera = cameraAt({1, 2, 3}, {4, -1, -5}, {0, 1, 0});
    const glm::dmat4 spot = glm::perspective(kFov, 1.0, 0.5, 50.0) * glm::inverse(camera.eyeToWorld);
    const glm::dvec3 slanted = glm::normalize(glm::dvec3(1, 2, 3));
    // Eye-space points inside the light's square frustum (|x|, |y| < tan 30 of the depth).
    for (const glm::dvec3 eye : {glm::dvec3(0, 0, -5), glm::dvec3(2, -1.5, -6), glm::dvec3(-9, 7, -20)}) {
        const glm::dvec3 point(camera.eyeToWorld * glm::dvec4(eye, 1.0));
        expectRelative(truth::texelOnScreen(point, slanted, camera, spot, kResolution), double(kHeight) / kResolution);
    }
}

// Grazing views along the ground y = 0, where only the perspective divide's dW term moves a
// point's image with its depth (clip y does not change along the view, w does). Eye or light
// at height h = 2 looking horizontally along -z, the point at depth d = 4 below the view axis
// at (0, 0, -4): its NDC y is -F h / d (F = 1 / tan of half the field of view), so a step along
// the ground's depth moves it by F h / d^2 per unit, a step across by F / d.
TEST(TexelMetric, ResolvesGrazingViewsThroughTheDivide) {
    constexpr double kH = 2.0, kD = 4.0, kHalfX = 4.0, kHalfZ = 16.0;
    constexpr int kResolution = 1024;
    const glm::dvec3 point(0, 0, -kD), up(0, 1, 0);
    const glm::dmat4 grazingView = glm::lookAt(glm::dvec3(0, kH, 0), glm::dvec3(0, kH, -1), up);
    const double focal = 1.0 / std::tan(kFov / 2);

    // A camera grazing the ground, the sun straight down: texels of 8/R across, 32/R along the
    // depth; on screen (Hpx/2 pixels per NDC unit, square pixels) those are
    // 8/R * 360 * F/4 = 720 F / R across and 32/R * 360 * F * 2/16 = 1440 F / R along.
    const engine::FrameCamera grazing = cameraAt({0, kH, 0}, {0, kH, -1}, up);
    expectRelative(truth::texelOnScreen(point, up, grazing, sunStraightDown(kHalfX, kHalfZ), kResolution),
                   2.0 * kHalfZ / kResolution * (kHeight / 2.0) * focal * kH / (kD * kD));

    // A spot light grazing the ground (field of view kFov, square), an orthographic camera
    // straight down showing 2V world units over Hpx pixels: a texel's edges on the ground are
    // (2/R) / (F h / d^2) = 2 d^2 / (R F h) along the depth and 2 d / (R F) across; the longer,
    // the one along the depth, is 16 / (R F) world units, Hpx / 2V pixels each.
    constexpr double kV = 5.0;
    engine::FrameCamera above = cameraAt({0, 10, 0}, {0, 0, 0}, {0, 0, -1});
    above.projection = glm::ortho(-kV * kWidth / kHeight, kV * kWidth / kHeight, -kV, kV, 0.1, 100.0);
    const glm::dmat4 spot = glm::perspective(kFov, 1.0, 0.1, 100.0) * grazingView;
    expectRelative(truth::texelOnScreen(point, up, above, spot, kResolution),
                   2.0 * kD * kD / (kResolution * focal * kH) * kHeight / (2.0 * kV));
}

// A wall (x = 1) under the straight-down sun: the map sees it as a line, no texel to measure.
// A point behind a spot light has no map position either.
TEST(TexelMetric, HasNoValueEdgeOnToTheLightOrBehindIt) {
    const engine::FrameCamera camera = cameraAt({8, 5, 8}, {1, 0.5, 0}, {0, 1, 0});
    EXPECT_TRUE(std::isnan(truth::texelOnScreen({1, 0.5, 0}, {1, 0, 0}, camera, sunStraightDown(8, 8), 1024)));
    const glm::dmat4 spotDown = glm::perspective(kFov, 1.0, 0.5, 50.0) *
                                glm::lookAt(glm::dvec3(0, 3, 0), glm::dvec3(0), glm::dvec3(0, 0, -1));
    EXPECT_FALSE(std::isnan(truth::texelOnScreen({0, 0, 0}, {0, 1, 0}, camera, spotDown, 1024)));
    EXPECT_TRUE(std::isnan(truth::texelOnScreen({1, 6, 0}, {0, 1, 0}, camera, spotDown, 1024)));
}

// Cascades by view depth (the last one for anything farther), cube faces by the major axis of
// the point minus the light (GL order +X -X +Y -Y +Z -Z), nothing from an unrendered layer.
TEST(TexelMetric, PicksTheLayerTheLookupUses) {
    engine::FrameCamera camera;  // at the origin, looking down -Z
    engine::ShadowView cascades;
    cascades.hasMap = true;
    cascades.layers.resize(3);
    for (engine::ShadowMapLayer& layer : cascades.layers) layer.rendered = true;
    cascades.cascadeSplits = {0.1, 5.0, 20.0, 100.0};
    EXPECT_EQ(truth::shadowLayerAt(cascades, camera, {1, 0, -3}), 0);
    EXPECT_EQ(truth::shadowLayerAt(cascades, camera, {0, 2, -10}), 1);
    EXPECT_EQ(truth::shadowLayerAt(cascades, camera, {0, 0, -500}), 2);
    cascades.layers[1].rendered = false;
    EXPECT_EQ(truth::shadowLayerAt(cascades, camera, {0, 2, -10}), -1);

    engine::ShadowView cube;
    cube.hasMap = cube.cube = true;
    const glm::dvec3 light(10, 20, 30);
    cube.layers.resize(6);
    for (engine::ShadowMapLayer& layer : cube.layers) {
        layer.lightToWorld = glm::translate(glm::dmat4(1.0), light);
        layer.rendered = true;
    }
    EXPECT_EQ(truth::shadowLayerAt(cube, camera, light + glm::dvec3(-1, 3, 0.5)), 2);
    EXPECT_EQ(truth::shadowLayerAt(cube, camera, light + glm::dvec3(2, -0.1, -5)), 5);
    EXPECT_EQ(truth::shadowLayerAt(cube, camera, light + glm::dvec3(-4, 1, 2)), 1);

    EXPECT_EQ(truth::shadowLayerAt(engine::ShadowView{}, camera, {0, 0, 0}), -1);  // no map
}
