// The error metrics on images small enough to work out by hand (no GL).
#include "truth/ShadowMetrics.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace truth {
namespace {

using Bytes = std::vector<std::uint8_t>;

TEST(ShadowMetrics, AcneAndLeakAreFractionsOfTheEvaluationSet) {
    // One row: two truly lit pixels (one half-shadowed by mistake), two truly shadowed
    // (one leaking a quarter of the light).
    const Bytes truth{1, 1, 0, 0};
    const std::vector<float> shade{1.0f, 0.5f, 0.0f, 0.25f};
    const Bytes all(4, 1);
    const ShadowErrors e = shadowErrors(4, 1, truth, shade, all, all);
    EXPECT_EQ(e.evaluated, 4u);
    EXPECT_DOUBLE_EQ(e.acne, 0.5 / 4);
    EXPECT_DOUBLE_EQ(e.leak, 0.25 / 4);
    EXPECT_DOUBLE_EQ(e.error, 0.75 / 4);
    // Pixels 1 and 2 sit on the lit/shadowed boundary; 0 and 3 remain.
    EXPECT_EQ(e.evaluatedNoEdge, 2u);
    EXPECT_DOUBLE_EQ(e.acneNoEdge, 0.0);
    EXPECT_DOUBLE_EQ(e.leakNoEdge, 0.25 / 2);
    EXPECT_DOUBLE_EQ(e.errorNoEdge, 0.25 / 2);
}

TEST(ShadowMetrics, PixelsOutsideTheEvaluationSetDoNotCount) {
    const Bytes truth{1, 1, 1, 1};
    const std::vector<float> shade{0.0f, 0.0f, 1.0f, 1.0f};
    const Bytes evaluation{0, 0, 1, 1};  // the wrong shadows lie outside E
    const ShadowErrors e = shadowErrors(4, 1, truth, shade, evaluation, Bytes(4, 1));
    EXPECT_EQ(e.evaluated, 2u);
    EXPECT_DOUBLE_EQ(e.error, 0.0);
}

TEST(ShadowMetrics, EdgeExclusionTakesTheEightNeighbourhood) {
    // 5x5, lit except the centre: the centre and its 8 neighbours are edge pixels.
    Bytes truth(25, 1);
    truth[2 * 5 + 2] = 0;
    const Bytes edges = truthEdges(5, 5, truth, Bytes(25, 1));
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x)
            EXPECT_EQ(edges[y * 5 + x], (x >= 1 && x <= 3 && y >= 1 && y <= 3) ? 1 : 0)
                << "pixel " << x << "," << y;

    // Everything shadowed by mistake: the error is the same with and without the edge ring.
    const std::vector<float> shade(25, 0.0f);
    const ShadowErrors e = shadowErrors(5, 5, truth, shade, Bytes(25, 1), Bytes(25, 1));
    EXPECT_EQ(e.evaluated, 25u);
    EXPECT_EQ(e.evaluatedNoEdge, 16u);
    EXPECT_DOUBLE_EQ(e.acne, 24.0 / 25);
    EXPECT_DOUBLE_EQ(e.acneNoEdge, 1.0);
    EXPECT_DOUBLE_EQ(e.leak, 0.0);
}

TEST(ShadowMetrics, BackgroundNeighboursMakeNoEdge) {
    // A lit surface against uncovered background (truth 0 there): a silhouette, not a shadow.
    const Bytes truth{1, 1, 0, 0};
    const Bytes covered{1, 1, 0, 0};
    EXPECT_EQ(truthEdges(4, 1, truth, covered), (Bytes{0, 0, 0, 0}));
    // Covered, the same values make an edge on both sides.
    EXPECT_EQ(truthEdges(4, 1, truth, Bytes(4, 1)), (Bytes{0, 1, 1, 0}));
}

TEST(ShadowMetrics, EdgesAcrossRowsUseDiagonals) {
    // 3x2, one shadowed pixel in a corner: its three neighbours, the diagonal one included,
    // are edge pixels; the left column touches none of it.
    const Bytes truth{1, 1, 1,
                      1, 1, 0};
    EXPECT_EQ(truthEdges(3, 2, truth, Bytes(6, 1)), (Bytes{0, 1, 1, 0, 1, 1}));
}

TEST(ShadowMetrics, EmptyEvaluationSetGivesZeros) {
    const ShadowErrors e = shadowErrors(2, 1, Bytes{1, 0}, std::vector<float>{0.0f, 1.0f},
                                        Bytes{0, 0}, Bytes{1, 1});
    EXPECT_EQ(e.evaluated, 0u);
    EXPECT_EQ(e.evaluatedNoEdge, 0u);
    EXPECT_EQ(e.error, 0.0);
    EXPECT_EQ(e.errorNoEdge, 0.0);
}

TEST(ShadowMetrics, ShadeIsClampedToTheUnitRange) {
    const ShadowErrors e = shadowErrors(2, 1, Bytes{1, 0}, std::vector<float>{-1.0f, 2.0f},
                                        Bytes{1, 1}, Bytes{1, 1});
    EXPECT_DOUBLE_EQ(e.acne, 0.5);
    EXPECT_DOUBLE_EQ(e.leak, 0.5);
}

TEST(ShadowMetrics, EightBitMaskMapsToShade) {
    const std::vector<float> shade = shadeFromMask8(Bytes{0, 51, 255});
    ASSERT_EQ(shade.size(), 3u);
    EXPECT_FLOAT_EQ(shade[0], 0.0f);
    EXPECT_FLOAT_EQ(shade[1], 0.2f);
    EXPECT_FLOAT_EQ(shade[2], 1.0f);
    // A mask straight from a PNG goes through the same metric.
    const ShadowErrors e =
        shadowErrors(3, 1, Bytes{1, 1, 1}, shadeFromMask8(Bytes{0, 255, 255}), Bytes(3, 1),
                     Bytes(3, 1));
    EXPECT_DOUBLE_EQ(e.acne, 1.0 / 3);
}

TEST(ShadowMetrics, MismatchedSizesAreRejected) {
    EXPECT_THROW(shadowErrors(2, 2, Bytes(4, 1), std::vector<float>(3, 1.0f), Bytes(4, 1),
                              Bytes(4, 1)),
                 std::invalid_argument);
    EXPECT_THROW(truthEdges(2, 2, Bytes(4, 1), Bytes(5, 1)), std::invalid_argument);
}

TEST(ShadowMetrics, AreaErrorsAreTheDistanceToTheLitFraction) {
    // A half-lit pixel shaded 0.5 (what 2x2 PCF gives on an edge) is right; a quarter-lit one
    // shaded fully lit leaks 0.75; a fully lit one shaded 0.25 has acne 0.75.
    const std::vector<float> fraction{0.5f, 0.25f, 1.0f};
    const std::vector<float> shade{0.5f, 1.0f, 0.25f};
    const ShadowErrors e =
        areaShadowErrors(3, 1, fraction, Bytes{1, 0, 1}, shade, Bytes(3, 1), Bytes(3, 1));
    EXPECT_EQ(e.evaluated, 3u);
    EXPECT_DOUBLE_EQ(e.acne, 0.75 / 3);
    EXPECT_DOUBLE_EQ(e.leak, 0.75 / 3);
    // The edge pixels come from the binary truth: all three touch its 1|0|1 boundary.
    EXPECT_EQ(e.evaluatedNoEdge, 0u);
}

TEST(ShadowMetrics, AreaErrorsOfABinaryFractionAreTheBinaryErrors) {
    const Bytes truth{1, 1, 0, 0, 1, 0};
    const std::vector<float> fraction{1, 1, 0, 0, 1, 0};
    const std::vector<float> shade{1.0f, 0.5f, 0.0f, 0.25f, 0.9f, 0.6f};
    const Bytes evaluation{1, 1, 1, 1, 0, 1};
    const ShadowErrors binary = shadowErrors(3, 2, truth, shade, evaluation, Bytes(6, 1));
    const ShadowErrors area = areaShadowErrors(3, 2, fraction, truth, shade, evaluation, Bytes(6, 1));
    EXPECT_DOUBLE_EQ(area.acne, binary.acne);
    EXPECT_DOUBLE_EQ(area.leak, binary.leak);
    EXPECT_DOUBLE_EQ(area.errorNoEdge, binary.errorNoEdge);
    EXPECT_EQ(area.evaluated, binary.evaluated);
    EXPECT_THROW(areaShadowErrors(3, 2, std::vector<float>(5), truth, shade, evaluation, Bytes(6, 1)),
                 std::invalid_argument);
}

} // namespace
} // namespace truth
