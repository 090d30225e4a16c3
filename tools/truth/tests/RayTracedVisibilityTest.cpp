// The ray-traced truth against shadows worked out by hand: the box over the plane, lit from
// straight above (spot, point) or along a slope (directional), near the origin and 10^6 away.
#include "truth/RayTracedVisibility.h"

#include "TruthTestScene.h"

#include "TruthGlTest.h"

#include "engine/render/SceneGpu.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace truth {
namespace {

using Type = engine::Light::Type;

// The plane points that must come out shadowed / lit, in plane coordinates (x, z), with a
// margin of 0.02 units around the analytic boundary, where a pixel may go either way.
constexpr double kMargin = 0.02;

// The box's shadow on y = 0. A light at (0,8,0) projects the top face (y = 3, 5 below it)
// by 8/5 and the bottom face (y = 1) by 8/7: the shadow is the top's square, half-size 1.6.
// The directional light along (s,-1,0) shifts a box slice at height y by s*y: the union of
// the slices y in [1,3] is x in [-1+s, 1+3s], z in [-1,1].
struct Rect { double x0, x1, z0, z1; };
Rect analyticShadow(Type type) {
    if (type == Type::Directional)
        return {-1.0 + test::kSlope, 1.0 + 3.0 * test::kSlope, -1.0, 1.0};
    const double half = 1.0 * test::kLightHeight / (test::kLightHeight - 3.0);
    return {-half, half, -half, half};
}

// Writes an 8-bit PGM for a person to look at when a check fails.
void writePgm(const std::string& name, int width, int height, const std::vector<std::uint8_t>& v) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream out(path, std::ios::binary);
    out << "P5\n" << width << " " << height << "\n255\n";
    for (std::uint8_t value : v) out.put(static_cast<char>(value ? 255 : 0));
    std::fprintf(stderr, "wrote %s\n", path.c_str());
}

struct Truth {
    SurfaceBuffer surfaces;
    std::vector<std::uint8_t> visible, evaluation;
};

Truth traceTruth(Type type, const glm::dvec3& offset, int width = 320, int height = 240) {
    const engine::Scene scene = test::boxOverPlane(type, offset);
    const engine::SceneGpu gpu(scene);
    Truth truth;
    truth.surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(width, height, offset));
    truth.visible = visibility(scene, 0, truth.surfaces);
    truth.evaluation = evaluationSet(scene, 0, truth.surfaces);
    return truth;
}

class RayTracedVisibilityTest : public test::TruthGlTest,
                                public ::testing::WithParamInterface<Type> {};

std::string typeName(const ::testing::TestParamInfo<Type>& info) {
    switch (info.param) {
    case Type::Spot: return "Spot";
    case Type::Point: return "Point";
    case Type::Directional: return "Directional";
    }
    return "Unknown";
}

TEST_P(RayTracedVisibilityTest, ShadowUnderTheBoxAndLightElsewhere) {
    const Type type = GetParam();
    const Truth truth = traceTruth(type, glm::dvec3(0.0));
    const Rect shadow = analyticShadow(type);
    std::size_t shadowed = 0, lit = 0, wrong = 0, boxTop = 0;
    for (std::size_t i = 0; i < truth.surfaces.pixelCount(); ++i) {
        if (!truth.surfaces.covered[i]) {
            EXPECT_EQ(truth.visible[i], 0);
            EXPECT_EQ(truth.evaluation[i], 0);
            continue;
        }
        const glm::dvec3& p = truth.surfaces.worldPosition[i];
        if (truth.surfaces.instance[i] == test::kBoxInstance) {
            // The top faces every one of these lights and nothing is above it.
            if (truth.surfaces.worldNormal[i].y > 0.99) {
                ++boxTop;
                EXPECT_EQ(truth.evaluation[i], 1);
                wrong += truth.visible[i] != 1;
            }
            continue;
        }
        if (!truth.evaluation[i]) continue;  // e.g. outside the spot cone, checked below
        const bool inside = p.x > shadow.x0 + kMargin && p.x < shadow.x1 - kMargin &&
                            p.z > shadow.z0 + kMargin && p.z < shadow.z1 - kMargin;
        const bool outside = p.x < shadow.x0 - kMargin || p.x > shadow.x1 + kMargin ||
                             p.z < shadow.z0 - kMargin || p.z > shadow.z1 + kMargin;
        if (inside) {
            ++shadowed;
            wrong += truth.visible[i] != 0;
        } else if (outside) {
            ++lit;
            wrong += truth.visible[i] != 1;
        }
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(shadowed, 500u);  // enough of the shadow is in view to mean something
    EXPECT_GT(lit, 10000u);
    EXPECT_GT(boxTop, 500u);
    // On failure, or on request (TRUTH_TEST_IMAGES=1), leave the images for a person.
    if (HasFailure() || std::getenv("TRUTH_TEST_IMAGES")) {
        writePgm("truth_" + typeName({type, 0}) + ".pgm", 320, 240, truth.visible);
        writePgm("evaluation_" + typeName({type, 0}) + ".pgm", 320, 240, truth.evaluation);
    }
}

TEST_P(RayTracedVisibilityTest, SameTruthTenToTheSixAwayFromTheOrigin) {
    const Truth near = traceTruth(GetParam(), glm::dvec3(0.0));
    const Truth far = traceTruth(GetParam(), glm::dvec3(1.0e6, 0.0, 1.0e6));
    std::size_t differ = 0, evaluationDiffers = 0;
    for (std::size_t i = 0; i < near.visible.size(); ++i) {
        differ += near.visible[i] != far.visible[i];
        evaluationDiffers += near.evaluation[i] != far.evaluation[i];
    }
    // Pixels exactly on a shadow boundary may flip with rounding; 0.1 % allows 76 of them.
    EXPECT_LE(differ, near.visible.size() / 1000) << differ << " pixels differ";
    EXPECT_LE(evaluationDiffers, near.visible.size() / 1000);
}

INSTANTIATE_TEST_SUITE_P(Lights, RayTracedVisibilityTest,
                         ::testing::Values(Type::Spot, Type::Point, Type::Directional), typeName);

using TruthGlTest = test::TruthGlTest;

TEST_F(TruthGlTest, SpotEvaluationSetStopsAtTheConeAndAtBackFaces) {
    engine::Scene scene = test::boxOverPlane(Type::Spot);
    scene.lights[0].outerConeAngle = 0.5;  // reaches the plane out to radius 8 tan(0.5) = 4.4
    const engine::SceneGpu gpu(scene);
    Truth truth;
    truth.surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(320, 240));
    truth.evaluation = evaluationSet(scene, 0, truth.surfaces);
    const double tanOuter = std::tan(0.5);  // cone radius on the plane / light height
    std::size_t inCone = 0, outOfCone = 0;
    for (std::size_t i = 0; i < truth.surfaces.pixelCount(); ++i) {
        if (!truth.surfaces.covered[i]) continue;
        const glm::dvec3& p = truth.surfaces.worldPosition[i];
        const glm::dvec3& n = truth.surfaces.worldNormal[i];
        if (truth.surfaces.instance[i] == test::kBoxInstance) {
            // Sides face away from a light straight above (N.L < 0 on x and z faces).
            if (std::abs(n.y) < 0.01) {
                ASSERT_EQ(truth.evaluation[i], 0);
            }
            continue;
        }
        const double radius = std::hypot(p.x, p.z) / test::kLightHeight;
        if (radius < tanOuter - 0.01) {
            ++inCone;
            ASSERT_EQ(truth.evaluation[i], 1) << "pixel " << i;
        } else if (radius > tanOuter + 0.01) {
            ++outOfCone;
            ASSERT_EQ(truth.evaluation[i], 0) << "pixel " << i;
        }
    }
    EXPECT_GT(inCone, 10000u);
    EXPECT_GT(outOfCone, 5000u);  // the plane's rim lies beyond the cone
}

TEST_F(TruthGlTest, RangeAndReceiveShadowsLimitTheEvaluationSet) {
    engine::Scene scene = test::boxOverPlane(Type::Point);
    scene.lights[0].range = 8.5;  // reaches the plane out to radius sqrt(8.5^2 - 8^2) ~ 2.87
    scene.nodes[1].receiveShadows = false;
    scene.updateWorldTransforms();
    const engine::SceneGpu gpu(scene);
    const SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(160, 120));
    const std::vector<std::uint8_t> evaluation = evaluationSet(scene, 0, surfaces);
    std::size_t inRange = 0;
    for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
        if (!surfaces.covered[i]) continue;
        if (surfaces.instance[i] == test::kBoxInstance) {
            ASSERT_EQ(evaluation[i], 0);  // the box receives no shadows
            continue;
        }
        const double distance = glm::length(surfaces.worldPosition[i] - glm::dvec3(0, 8, 0));
        if (distance < 8.5 - 1e-3) inRange += evaluation[i];
        if (distance > 8.5 + 1e-3) {
            ASSERT_EQ(evaluation[i], 0);
        }
    }
    EXPECT_GT(inRange, 100u);
}

TEST_F(TruthGlTest, NonCastersCastNoShadow) {
    engine::Scene scene = test::boxOverPlane(Type::Spot);
    scene.nodes[1].castShadows = false;
    scene.updateWorldTransforms();
    const engine::SceneGpu gpu(scene);
    const SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(160, 120));
    const RayTracedVisibility tracer(scene);
    EXPECT_EQ(tracer.triangleCount(), 2u);  // the plane only
    const std::vector<std::uint8_t> visible = tracer.visibility(scene, 0, surfaces);
    const std::vector<std::uint8_t> evaluation = evaluationSet(scene, 0, surfaces);
    for (std::size_t i = 0; i < visible.size(); ++i)
        if (evaluation[i]) {
            ASSERT_EQ(visible[i], 1) << "pixel " << i;
        }
}

TEST_F(TruthGlTest, BadLightIndexIsRejected) {
    const engine::Scene scene = test::boxOverPlane(Type::Spot);
    const SurfaceBuffer empty;
    EXPECT_THROW(visibility(scene, 1, empty), std::invalid_argument);
    EXPECT_THROW(evaluationSet(scene, -1, empty), std::invalid_argument);
}

// A 640x360 truth image: one ray per covered pixel, each answered lit (1) or shadowed (0),
// both present (the box shadows the plane under the spot). Its speed is a benchmark, not a
// test (machines differ): engine-microbench --benchmark_filter=Truth.
TEST_F(TruthGlTest, TracesEveryCoveredPixelOfA640x360Frame) {
    const engine::Scene scene = test::boxOverPlane(Type::Spot);
    const engine::SceneGpu gpu(scene);
    const SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(640, 360));
    const std::vector<std::uint8_t> visible = RayTracedVisibility(scene).visibility(scene, 0, surfaces);
    ASSERT_EQ(visible.size(), surfaces.covered.size());
    std::size_t covered = 0, lit = 0, shadowed = 0, uncoveredLit = 0;
    for (std::size_t i = 0; i < visible.size(); ++i) {
        if (!surfaces.covered[i]) {
            uncoveredLit += visible[i] != 0;
            continue;
        }
        ++covered;
        ASSERT_LE(visible[i], 1) << "pixel " << i;
        (visible[i] ? lit : shadowed) += 1;
    }
    std::printf("truth 640x360: %zu covered pixels, %zu lit, %zu shadowed\n", covered, lit, shadowed);
    // Measured 96741 covered (84650 lit, 12091 shadowed) of 230400 pixels; bound +-1000, about
    // half the covered silhouette's perimeter, for a rasterizer that rounds its edges otherwise.
    EXPECT_NEAR(double(covered), 96741.0, 1000.0);
    EXPECT_GT(lit, 0u);
    EXPECT_GT(shadowed, 0u);
    EXPECT_EQ(uncoveredLit, 0u);
}

} // namespace
} // namespace truth
