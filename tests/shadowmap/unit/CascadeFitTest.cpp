// Cascades of a directional light (math/CascadeFit.h): the practical split distances, each
// cascade's box fitted to its slice of the camera frustum and the casters over it, and the
// stable mode's snapping (a camera moved by less than one texel keeps a cascade's matrix,
// by one texel moves it by exactly one), and what `cascades: auto` weighs and chooses.
#include "math/CascadeFit.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace {

using engine::Aabb;
using shadowmap::CascadeCamera;
using shadowmap::CascadeOptions;
using shadowmap::CascadeViews;
using shadowmap::ShadowBounds;

constexpr double kFovY = 0.9, kAspect = 16.0 / 9.0, kNear = 0.1, kFar = 100.0;
const Aabb kGround{{-500, -0.1, -500}, {500, 0, 500}};
const Aabb kPost{{-0.05, 0, -5.05}, {0.05, 3, -4.95}};

CascadeCamera cameraAt(const glm::dvec3& eye, const glm::dvec3& target) {
    CascadeCamera camera;
    camera.eyeToWorld = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
    camera.projection = glm::perspective(kFovY, kAspect, kNear, kFar);
    return camera;
}

// A directional light node shining along `direction` (glTF lights shine down -Z).
engine::LightInstance sunShining(const glm::dvec3& direction) {
    engine::LightInstance sun;
    sun.world = shadowmap::lightToWorldFromDirection(glm::dvec3(0.0), direction);
    return sun;
}

ShadowBounds groundAndPost() {
    ShadowBounds bounds;
    bounds.receivers = {kGround, kPost};
    bounds.casters = {kGround, kPost};
    return bounds;
}

Aabb sceneBox() {
    Aabb box = kGround;
    box.extend(kPost);
    return box;
}

CascadeViews fit(const CascadeCamera& camera, const glm::dvec3& sunDirection, bool stable, int count = 4,
                 double blend = 0.0) {
    CascadeOptions options;
    options.count = count;
    options.blend = blend;
    options.lambda = 0.5;
    options.stable = stable;
    options.resolution = 1024;
    return shadowmap::fitDirectionalCascades(sunShining(sunDirection), engine::Light{}, groundAndPost(), sceneBox(),
                                             camera, options);
}

TEST(CascadeSplits, PracticalSchemeBlendsLogarithmicAndUniform) {
    const std::vector<double> logarithmic = shadowmap::cascadeSplits(1.0, 1000.0, 3, 1.0);
    const std::vector<double> uniform = shadowmap::cascadeSplits(1.0, 1000.0, 3, 0.0);
    const std::vector<double> half = shadowmap::cascadeSplits(1.0, 1000.0, 3, 0.5);
    const double expectedLog[] = {1, 10, 100, 1000}, expectedUniform[] = {1, 334, 667, 1000};
    ASSERT_EQ(logarithmic.size(), 4u);
    for (int i = 0; i < 4; ++i) {
        // pow and the sums round: a few ulps of 1000.
        EXPECT_NEAR(logarithmic[i], expectedLog[i], 1e-12 * 1000) << i;
        EXPECT_NEAR(uniform[i], expectedUniform[i], 1e-12 * 1000) << i;
        EXPECT_NEAR(half[i], 0.5 * (expectedLog[i] + expectedUniform[i]), 1e-12 * 1000) << i;
    }
    // The ends are exact, so every depth in [near, far] falls in some cascade.
    EXPECT_EQ(half.front(), 1.0);
    EXPECT_EQ(half.back(), 1000.0);
}

TEST(CascadeSplits, RangeIsWhereVisibleReceiversAre) {
    const CascadeCamera camera = cameraAt({0, 2, 0}, {0, 2, -10});
    double nearDepth = 0, farDepth = 0;
    // The ground runs past both camera planes: clamped to them.
    ASSERT_TRUE(shadowmap::receiverDepthRange(camera, {kGround}, nearDepth, farDepth));
    EXPECT_NEAR(nearDepth, kNear, 1e-9);
    EXPECT_NEAR(farDepth, kFar, 1e-9);
    // A lone post 5 m ahead: its own depths (4.95 .. 5.05).
    ASSERT_TRUE(shadowmap::receiverDepthRange(camera, {kPost}, nearDepth, farDepth));
    EXPECT_NEAR(nearDepth, 4.95, 1e-9);
    EXPECT_NEAR(farDepth, 5.05, 1e-9);
    // Behind the camera: nothing to shadow.
    EXPECT_FALSE(shadowmap::receiverDepthRange(camera, {Aabb{{-1, 0, 1}, {1, 1, 2}}}, nearDepth, farDepth));
}

TEST(CascadeFit, EachCascadeHoldsItsSliceAndTheCastersOverIt) {
    // Sun straight down: the light frame's x is world -x and its y world z, so each slice's
    // footprint is known in closed form: width 2 d1 tan(fovy/2) aspect, length d1 - d0.
    const CascadeCamera camera = cameraAt({0, 2, 0}, {0, 2, -10});
    const CascadeViews views = fit(camera, {0, -1, 0}, false);
    ASSERT_TRUE(views.valid) << views.invalidReason;
    ASSERT_EQ(views.cascades.size(), 4u);
    ASSERT_EQ(views.splits.size(), 5u);
    const double tanHalf = std::tan(0.5 * kFovY);
    double previousWidth = 0.0;
    for (int i = 0; i < 4; ++i) {
        const shadowmap::LightView& view = views.cascades[i];
        ASSERT_TRUE(view.valid && !view.empty) << i;
        const double width = 2.0 / view.projection[0][0], length = 2.0 / view.projection[1][1];
        const double d0 = views.splits[i], d1 = views.splits[i + 1];
        // The margins widen each side by 1e-3 of the largest side (FrustumFitOptions).
        const double margin = 2e-3 * std::max(width, view.farPlane) + 1e-12;
        EXPECT_NEAR(width, 2.0 * d1 * tanHalf * kAspect, margin) << i;
        EXPECT_NEAR(length, d1 - d0, margin) << i;
        EXPECT_GT(width, previousWidth) << "nearer cascades have the smaller texels";
        previousWidth = width;
        // Depth: from the ground's underside up to the top of the post, which stands in
        // every slice's footprint column here or not: check only those it overlaps.
        const glm::dvec3 eye(view.lightToWorld[3]);
        EXPECT_LE(eye.y - view.farPlane, kGround.min.y + 1e-9) << i;
        if (-kPost.max.z <= d1 && -kPost.min.z >= d0) {
            EXPECT_GE(eye.y, kPost.max.y) << i;
        }
    }
    // Cascade 0 against one map for the whole slice range: its texels are smaller by the
    // ratio of the widths (what cascades are for).
    const CascadeViews single = fit(camera, {0, -1, 0}, false, 1);
    EXPECT_LT(2.0 / views.cascades[0].projection[0][0], 0.2 * 2.0 / single.cascades[0].projection[0][0]);
}

TEST(CascadeFit, NoVisibleReceiverIsEmpty) {
    ShadowBounds bounds;
    bounds.receivers = {Aabb{{-1, 0, 1}, {1, 1, 2}}};  // behind the camera
    CascadeOptions options;
    options.count = 2;
    const CascadeViews views = shadowmap::fitDirectionalCascades(
        sunShining({0, -1, 0}), engine::Light{}, bounds, bounds.receivers[0], cameraAt({0, 2, 0}, {0, 2, -10}), options);
    EXPECT_TRUE(views.valid);
    EXPECT_TRUE(views.empty);
}

// shadow_distance: the slices end there (their maps cover no farther, so even one slice's
// texels shrink), and receivers only beyond it leave nothing to shadow.
TEST(CascadeFit, AShadowDistanceEndsTheSlices) {
    const CascadeCamera camera = cameraAt({0, 2, 0}, {0, 2, -10});
    CascadeOptions options;
    options.count = 1;
    options.maxDistance = 20.0;
    double nearDepth = 0, farDepth = 0;
    ASSERT_TRUE(shadowmap::shadowedDepthRange(camera, {kGround}, options, nearDepth, farDepth));
    EXPECT_NEAR(farDepth, 20.0, 1e-9);
    const CascadeViews limited = shadowmap::fitDirectionalCascades(sunShining({0, -1, 0}), engine::Light{},
                                                                   groundAndPost(), sceneBox(), camera, options);
    ASSERT_TRUE(limited.valid && !limited.empty);
    EXPECT_EQ(limited.splits.back(), 20.0);
    options.maxDistance = 0.0;  // no limit: the camera's far plane
    const CascadeViews whole = shadowmap::fitDirectionalCascades(sunShining({0, -1, 0}), engine::Light{},
                                                                 groundAndPost(), sceneBox(), camera, options);
    ASSERT_TRUE(whole.valid && !whole.empty);
    EXPECT_NEAR(whole.splits.back(), kFar, 1e-9);
    // The sun straight down: the map's width is the slice's far width, 2 d tan(fovy/2) aspect.
    EXPECT_LT(2.0 / limited.cascades[0].projection[0][0], 0.25 * 2.0 / whole.cascades[0].projection[0][0]);
    // Only the post, 5 m ahead, beyond a distance of 3: nothing to shadow.
    options.maxDistance = 3.0;
    EXPECT_FALSE(shadowmap::shadowedDepthRange(camera, {kPost}, options, nearDepth, farDepth));
    ShadowBounds post;
    post.receivers = post.casters = {kPost};
    EXPECT_TRUE(shadowmap::fitDirectionalCascades(sunShining({0, -1, 0}), engine::Light{}, post, kPost, camera, options)
                    .empty);
    // A directional map is a slice of the view with several cascades or with a distance.
    EXPECT_FALSE(shadowmap::directionalMapIsSliced(1, 0.0));
    EXPECT_TRUE(shadowmap::directionalMapIsSliced(1, 20.0));
    EXPECT_TRUE(shadowmap::directionalMapIsSliced(3, 0.0));
}

// The sun at 35 degrees above the horizon, from an azimuth that does not line up with any axis.
const glm::dvec3 kSun = glm::normalize(glm::dvec3(std::cos(0.61) * std::cos(0.4), -std::sin(0.61),
                                                  std::cos(0.61) * std::sin(0.4)));

TEST(CascadeStable, SubTexelMovesKeepTheMatrixAndWholeTexelsMoveItByOne) {
    const glm::dvec3 eye(3, 1.7, 2), target(10, 1, -20);
    const CascadeViews start = fit(cameraAt(eye, target), kSun, true);
    ASSERT_TRUE(start.valid && !start.empty);
    for (int c = 0; c < 4; ++c) {
        const shadowmap::LightView& first = start.cascades[c];
        const glm::dvec3 axis(first.lightToWorld[0]);  // the light frame's x, in world space
        const double texel = 2.0 / (first.projection[0][0] * 1024);
        auto cascadeAt = [&](double offset) { return fit(cameraAt(eye + offset * axis, target + offset * axis), kSun, true).cascades[c]; };
        // Walk in twentieths of a texel until the snapped position steps: just past a step.
        double crossing = -1.0;
        for (int step = 1; step <= 22 && crossing < 0.0; ++step)
            if (cascadeAt(step * 0.05 * texel).lightToWorld != first.lightToWorld) crossing = step * 0.05 * texel;
        ASSERT_GT(crossing, 0.0) << "cascade " << c << " never moved within 1.1 texels";
        const shadowmap::LightView atStep = cascadeAt(crossing);
        // Less than a texel further (at most 0.05 + 0.9 past the step): the same matrix.
        const shadowmap::LightView subTexel = cascadeAt(crossing + 0.9 * texel);
        EXPECT_EQ(subTexel.lightToWorld, atStep.lightToWorld) << c;
        EXPECT_EQ(subTexel.projection, atStep.projection) << c;
        // One texel further: exactly one texel along x, nothing else.
        const shadowmap::LightView oneTexel = cascadeAt(crossing + texel);
        const glm::dvec3 moved = glm::dvec3(oneTexel.lightToWorld[3]) - glm::dvec3(atStep.lightToWorld[3]);
        // Positions of a few hundred units carry ~1e-13 of rounding per operation.
        EXPECT_NEAR(glm::dot(moved, axis), texel, 1e-9) << c;
        EXPECT_NEAR(glm::length(moved - glm::dot(moved, axis) * axis), 0.0, 1e-9) << c;
        EXPECT_EQ(oneTexel.projection, atStep.projection) << c;
    }
    // Control: without stable mode a quarter-texel move already changes the matrix.
    const CascadeViews fitted = fit(cameraAt(eye, target), kSun, false);
    const glm::dvec3 axis(fitted.cascades[0].lightToWorld[0]);
    const double texel = 2.0 / (fitted.cascades[0].projection[0][0] * 1024);
    const CascadeViews nudged = fit(cameraAt(eye + 0.25 * texel * axis, target + 0.25 * texel * axis), kSun, false);
    EXPECT_NE(nudged.cascades[0].lightToWorld, fitted.cascades[0].lightToWorld);
}

// cascade_blend: a fitted cascade but the last reaches over the band past its far split (the
// lookup fades into the next one there); the last one and stable cascades keep their views.
TEST(CascadeFit, ABlendBandWidensFittedCascadesButTheLastAndNotStableOnes) {
    const CascadeCamera camera = cameraAt({0, 1.7, 0}, {0, 1.0, -20});
    const CascadeViews hard = fit(camera, kSun, false), blended = fit(camera, kSun, false, 4, 0.5);
    ASSERT_EQ(hard.splits, blended.splits);  // the lookup's splits do not move
    for (int c = 0; c < 3; ++c) {
        // The orthographic extent (2 / P00) of cascade c, wider with the band.
        EXPECT_GT(2.0 / blended.cascades[c].projection[0][0] + 2.0 / blended.cascades[c].projection[1][1],
                  2.0 / hard.cascades[c].projection[0][0] + 2.0 / hard.cascades[c].projection[1][1])
            << "cascade " << c;
    }
    EXPECT_EQ(blended.cascades[3].projection, hard.cascades[3].projection);
    const CascadeViews stableHard = fit(camera, kSun, true), stableBlended = fit(camera, kSun, true, 4, 0.5);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(stableBlended.cascades[c].projection, stableHard.cascades[c].projection) << c;
}

TEST(CascadeStable, RadiusIsQuantizedUpAndSnappingRoundsToTheNearestTexel) {
    EXPECT_EQ(shadowmap::quantizedRadius(1.0), 1.0);
    EXPECT_EQ(shadowmap::quantizedRadius(2.0), 2.0);
    const double r = shadowmap::quantizedRadius(1.05);
    EXPECT_GE(r, 1.05);
    EXPECT_LE(r, 1.05 * std::exp2(1.0 / 8.0));
    EXPECT_EQ(shadowmap::quantizedRadius(1.04), shadowmap::quantizedRadius(1.05));  // both in (1, 2^(1/8)]
    EXPECT_EQ(shadowmap::snapToTexel(0.26, 0.5), 0.5);
    EXPECT_EQ(shadowmap::snapToTexel(0.24, 0.5), 0.0);
    EXPECT_EQ(shadowmap::snapToTexel(-0.74, 0.5), -0.5);
}

// A need whose nearest texels per pixel are `nearest` and whose mean texels are `mean`.
shadowmap::CascadeNeed needOf(const std::array<double, 4>& nearest, const std::array<double, 4>& mean) {
    shadowmap::CascadeNeed need;
    for (int count = 1; count <= 4; ++count) {
        need.texelsPerPixel[count] = nearest[count - 1];
        need.meanTexel[count] = mean[count - 1];
    }
    return need;
}

TEST(CascadeAuto, AddsACascadeWhileItShrinksTheMeanTexelEnough) {
    using shadowmap::autoCascadeCount;
    // Mean gains as measured (CascadeFit.h): the showcase's sun 0.90 (one map), the outdoor
    // scene 7.86, 1.54, 1.23 (three cascades) and, with the camera's near plane at 20 m,
    // 3.62, 1.28, 1.15 (two).
    EXPECT_EQ(autoCascadeCount(needOf({2.9, 2.1, 1.4, 1.1}, {1.0, 1.0 / 0.90, 1.0 / 0.90 / 1.26, 0.7}), 0), 1);
    EXPECT_EQ(autoCascadeCount(needOf({2260, 180, 107, 82}, {786, 100, 100 / 1.54, 100 / 1.54 / 1.23}), 0), 3);
    EXPECT_EQ(autoCascadeCount(needOf({11, 2, 1.3, 1.0}, {362, 100, 100 / 1.28, 60}), 0), 2);
    // Every gain large: all four.
    EXPECT_EQ(autoCascadeCount(needOf({1000, 100, 10, 2}, {1000, 100, 10, 1}), 0), 4);
    // A map whose nearest texel is a pixel or less needs nothing finer, whatever the gain.
    EXPECT_EQ(autoCascadeCount(needOf({0.9, 0.1, 0.01, 0.001}, {10, 1, 0.1, 0.01}), 0), 1);
    EXPECT_EQ(autoCascadeCount(needOf({50, 1.0, 0.1, 0.01}, {10, 1, 0.1, 0.01}), 0), 2);
    // A count that gives no map (infinite need) is never chosen, nor what lies past it.
    constexpr double kNone = std::numeric_limits<double>::infinity();
    EXPECT_EQ(autoCascadeCount(needOf({10, kNone, 1, 0.5}, {10, kNone, 1, 0.5}), 0), 1);
    EXPECT_EQ(autoCascadeCount(needOf({kNone, kNone, kNone, kNone}, {kNone, kNone, kNone, kNone}), 0), 1);
}

TEST(CascadeAuto, ACascadeInUseStaysWhileItGainsAlmostEnough) {
    using shadowmap::autoCascadeCount;
    // Gain 1.32 from one map to two: not enough to add the second, enough to keep it.
    const shadowmap::CascadeNeed borderline = needOf({10, 8, 7, 6}, {13.2, 10, 9, 8.5});
    EXPECT_EQ(autoCascadeCount(borderline, 0), 1);
    EXPECT_EQ(autoCascadeCount(borderline, 1), 1);
    EXPECT_EQ(autoCascadeCount(borderline, 2), 2);
    // Below the keeping gain (1.28) it goes.
    EXPECT_EQ(autoCascadeCount(needOf({10, 8, 7, 6}, {12.8, 10, 9, 8.5}), 2), 1);
}

// On the ground-and-post scene seen from street level, one map spreads 1 km of ground over
// its texels while the nearest cascade covers metres: the need drops by orders of magnitude
// from one map to two, and each further cascade shrinks the nearest slice and the mean again.
TEST(CascadeAuto, NeedIsTheNearestTexelOverThePixelThere) {
    CascadeOptions options;
    options.lambda = 0.5;
    options.stable = true;
    options.resolution = 1024;
    const CascadeCamera camera = cameraAt({0, 1.7, 0}, {0, 1.0, -20});
    const shadowmap::CascadeNeed need = shadowmap::cascadeNeed(
        sunShining(kSun), engine::Light{}, groundAndPost(), sceneBox(), camera, options, 720);
    for (int count = 1; count <= 4; ++count) EXPECT_TRUE(std::isfinite(need.texelsPerPixel[count])) << count;
    EXPECT_GT(need.texelsPerPixel[1] / need.texelsPerPixel[2], 10.0);
    EXPECT_GT(need.texelsPerPixel[2], need.texelsPerPixel[3]);
    EXPECT_GT(need.texelsPerPixel[3], need.texelsPerPixel[4]);
    for (int count = 1; count < 4; ++count) EXPECT_GT(need.meanTexel[count], need.meanTexel[count + 1]) << count;
    // One map's texel: the ground box in the light frame (about 1 km across) over 1024; a
    // pixel at the nearest receiver depth (the camera's near plane, 0.1: the ground's box
    // holds the camera) is 0.1 * 2 tan(0.45) / 720. The ratio is in the thousands.
    EXPECT_GT(need.texelsPerPixel[1], 1000.0);
    // No viewport height, no need: every count infinite (auto then keeps one map).
    const shadowmap::CascadeNeed unknown = shadowmap::cascadeNeed(
        sunShining(kSun), engine::Light{}, groundAndPost(), sceneBox(), camera, options, 0);
    EXPECT_TRUE(std::isinf(unknown.texelsPerPixel[1]));
}

} // namespace
