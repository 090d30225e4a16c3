// Which level a depth pass draws (technique/CasterLodChoice.h): a texel's world size from the
// view's clip space, against the closed forms for a perspective and an orthographic map; the
// instance's scale; the coarsest level within the allowance.
#include "technique/CasterLodChoice.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace {

engine::Aabb box(const glm::dvec3& centre, double half) {
    engine::Aabb b;
    b.extend(centre - glm::dvec3(half));
    b.extend(centre + glm::dvec3(half));
    return b;
}

} // namespace

TEST(CasterLodChoice, PerspectiveTexelIsTwoDTanHalfFovOverResolution) {
    const double fov = glm::radians(60.0);
    const glm::dmat4 viewProjection = glm::perspective(fov, 1.0, 0.1, 100.0) *
                                      glm::lookAt(glm::dvec3(0, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
    // A small box on the axis at depth 10 (its nearest face at 9.9).
    const double texel = shadowmap::texelSizeAt(viewProjection, box({0, 0, -10}, 0.1), 1024);
    const double expected = 2.0 * 9.9 * std::tan(fov / 2.0) / 1024.0;
    // The corners are 0.1 off the axis, where x/w's gradient is a little larger (finer texels).
    EXPECT_NEAR(texel, expected, 1e-3 * expected);
    EXPECT_LE(texel, expected * (1.0 + 1e-12));
    // Twice as far: twice the texel.
    EXPECT_NEAR(shadowmap::texelSizeAt(viewProjection, box({0, 0, -20}, 0.1), 1024) / texel, 19.9 / 9.9, 1e-3);
    // A box reaching the light's plane: texels down to nothing.
    EXPECT_EQ(shadowmap::texelSizeAt(viewProjection, box({0, 0, -0.5}, 1.0), 1024), 0.0);
}

TEST(CasterLodChoice, OrthographicTexelIsExtentOverResolution) {
    const glm::dmat4 viewProjection = glm::ortho(-8.0, 8.0, -4.0, 4.0, 0.0, 50.0);
    // The finer of the two axes: 8 / 512 across y.
    EXPECT_DOUBLE_EQ(shadowmap::texelSizeAt(viewProjection, box({1, 1, -10}, 0.5), 512), 8.0 / 512.0);
}

TEST(CasterLodChoice, LargestScaleOfATransform) {
    EXPECT_NEAR(shadowmap::largestScale(glm::dmat4(1.0)), 1.0, 1e-5);
    const glm::dmat4 turned = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3)));
    const glm::dmat4 stretched = glm::scale(turned, glm::dvec3(0.5, 3.0, 1.5));
    EXPECT_GE(shadowmap::largestScale(stretched), 3.0);
    EXPECT_NEAR(shadowmap::largestScale(stretched), 3.0, 1e-5);
}

TEST(CasterLodChoice, CoarsestLevelWithinTheAllowance) {
    const std::vector<double> errors{0.01, 0.02, 0.05};
    EXPECT_EQ(shadowmap::coarsestLevelWithin(errors, 1.0, 0.005), 0);
    EXPECT_EQ(shadowmap::coarsestLevelWithin(errors, 1.0, 0.02), 2);
    EXPECT_EQ(shadowmap::coarsestLevelWithin(errors, 2.0, 0.02), 1);  // the instance doubles every error
    EXPECT_EQ(shadowmap::coarsestLevelWithin(errors, 1.0, 1.0), 3);
    EXPECT_EQ(shadowmap::coarsestLevelWithin({}, 1.0, 1.0), 0);
}
