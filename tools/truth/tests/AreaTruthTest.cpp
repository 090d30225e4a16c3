// The area truth (lit fraction of each pixel's footprint) against the binary truth traced at
// four times the resolution: the 4x4 samples of a pixel are exactly the centres of the 4x4
// fine pixels it covers, so on a flat receiver both must count the same lit samples.
#include "truth/RayTracedVisibility.h"

#include "TruthTestScene.h"

#include "TruthGlTest.h"

#include "engine/render/SceneGpu.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace truth {
namespace {

using Type = engine::Light::Type;
using AreaTruthTest = test::TruthGlTest;

constexpr int kWidth = 80, kHeight = 60, kFine = 4;  // kFine = samples per axis of litFraction

struct FineBlock {
    bool onePlane = true;  // every fine pixel covered, on the coarse pixel's plane
    int lit = 0;           // fine pixels whose binary truth is lit
};

// The box and plane are exact planes, so "same plane" only has to absorb float rounding of
// the captured points (~1e-6 of the 12-unit view distance): 1e-4 units, and normals within
// 2.6 degrees — any other face of the box is 90 degrees off.
FineBlock fineBlock(const SurfaceBuffer& coarse, std::size_t i, const SurfaceBuffer& fine,
                    const std::vector<std::uint8_t>& fineVisible, int x, int y) {
    const glm::dvec3& p = coarse.worldPosition[i];
    const glm::dvec3& n = coarse.worldNormal[i];
    FineBlock block;
    for (int dy = 0; dy < kFine; ++dy)
        for (int dx = 0; dx < kFine; ++dx) {
            const std::size_t f = static_cast<std::size_t>(y * kFine + dy) * fine.width + x * kFine + dx;
            const bool samePlane = fine.covered[f] && glm::dot(fine.worldNormal[f], n) > 0.999 &&
                                   std::abs(glm::dot(fine.worldPosition[f] - p, n)) < 1e-4;
            if (!samePlane) block.onePlane = false;
            block.lit += fineVisible[f];
        }
    return block;
}

void expectFractionsMatchFineTruth(Type type) {
    const engine::Scene scene = test::boxOverPlane(type);
    const engine::SceneGpu gpu(scene);
    const RayTracedVisibility tracer(scene);
    const SurfaceBuffer coarse = SurfaceCapture().capture(scene, gpu, test::sideCamera(kWidth, kHeight));
    const SurfaceBuffer fine =
        SurfaceCapture().capture(scene, gpu, test::sideCamera(kWidth * kFine, kHeight * kFine));
    const std::vector<float> fraction = tracer.litFraction(scene, 0, coarse);
    const std::vector<std::uint8_t> fineVisible = tracer.visibility(scene, 0, fine);
    ASSERT_EQ(fraction.size(), coarse.pixelCount());

    std::size_t compared = 0, partial = 0, offByMoreThanOneSample = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
            if (!coarse.covered[i]) {
                ASSERT_EQ(fraction[i], 0.0f) << "uncovered pixel " << i;
                continue;
            }
            ASSERT_GE(fraction[i], 0.0f);
            ASSERT_LE(fraction[i], 1.0f);
            const FineBlock block = fineBlock(coarse, i, fine, fineVisible, x, y);
            if (!block.onePlane) continue;  // a silhouette or a crease: litFraction extends the
                                            // centre's plane, the fine trace does not
            ++compared;
            partial += fraction[i] > 0.0f && fraction[i] < 1.0f;
            // A sample within rounding of the shadow boundary may land either side in the two
            // traces (fine: rasterized point; coarse: camera ray met with the plane).
            const double samples = fraction[i] * kFine * kFine;
            offByMoreThanOneSample += std::abs(samples - block.lit) > 1.0;
        }
    EXPECT_EQ(offByMoreThanOneSample, 0u);
    // The box's shadow outline crosses the plane in view: its pixels are partly lit.
    // 80x60 shows about 40 such pixels per light (counted); at least 10 is a loose floor.
    EXPECT_GT(partial, 10u);
    std::printf("compared %zu pixels, %zu partly lit\n", compared, partial);
    EXPECT_GT(compared, static_cast<std::size_t>(kWidth * kHeight / 4));
}

TEST_F(AreaTruthTest, DirectionalFractionsMatchTheFineBinaryTruth) {
    expectFractionsMatchFineTruth(Type::Directional);
}

TEST_F(AreaTruthTest, SpotFractionsMatchTheFineBinaryTruth) { expectFractionsMatchFineTruth(Type::Spot); }

TEST_F(AreaTruthTest, CameraThatDoesNotMatchThePixelsIsRejected) {
    const engine::Scene scene = test::boxOverPlane(Type::Spot);
    const engine::SceneGpu gpu(scene);
    SurfaceBuffer surfaces = SurfaceCapture().capture(scene, gpu, test::sideCamera(16, 12));
    surfaces.camera.width = 32;
    EXPECT_THROW(RayTracedVisibility(scene).litFraction(scene, 0, surfaces), std::invalid_argument);
    EXPECT_THROW(RayTracedVisibility(scene).litFraction(scene, 2, surfaces), std::invalid_argument);
}

} // namespace
} // namespace truth
