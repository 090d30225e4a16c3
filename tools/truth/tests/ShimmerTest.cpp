// Shimmer between two frames (truth/Shimmer.h) on hand-made captures: a ground seen straight
// down by an orthographic camera, the second frame's camera moved sideways. A shadow edge
// fixed on the ground does not shimmer; one that moves with the camera does; pixels whose
// points do not land on a pixel centre of the other frame are not compared.
#include "truth/Shimmer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <vector>

namespace {

constexpr int kSize = 8;  // pixels per side; one world unit per pixel

struct Frame {
    truth::SurfaceBuffer surfaces;
    std::vector<std::uint8_t> mask, truth, evaluated;
    truth::ShimmerFrame view() const { return {&surfaces, mask, truth, evaluated}; }
};

// The ground (y = 0) seen from 10 units above (offsetX, 0, 0); `shadowed(x)` says where
// the mask is dark, by the world x of the pixel's point; the truth is lit everywhere.
template <typename Shadowed>
Frame groundFrame(double offsetX, Shadowed shadowed) {
    Frame frame;
    truth::SurfaceBuffer& s = frame.surfaces;
    s.width = s.height = kSize;
    s.camera.width = s.camera.height = kSize;
    s.camera.eyeToWorld = glm::inverse(glm::lookAt(glm::dvec3(offsetX, 10, 0), glm::dvec3(offsetX, 0, 0), glm::dvec3(0, 0, -1)));
    s.camera.projection = glm::ortho(-4.0, 4.0, -4.0, 4.0, 0.1, 100.0);
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) {
            const glm::dvec4 eye(column + 0.5 - 4.0, 4.0 - (row + 0.5), -10.0, 1.0);
            const glm::dvec3 world(s.camera.eyeToWorld * eye);
            s.worldPosition.push_back(world);
            s.worldNormal.emplace_back(0, 1, 0);
            s.covered.push_back(1);
            s.instance.push_back(0);
            s.receivesShadows.push_back(1);
            frame.mask.push_back(shadowed(world.x, column) ? 0 : 255);
            frame.truth.push_back(1);
            frame.evaluated.push_back(1);
        }
    return frame;
}

TEST(Shimmer, AnEdgeFixedOnTheGroundDoesNotShimmerOneThatMovesDoes) {
    const auto fixedEdge = [](double x, int) { return x < 0.0; };
    const Frame a = groundFrame(0.0, fixedEdge), b = groundFrame(1.0, fixedEdge);
    const truth::ShimmerCount still = truth::shimmerBetween(a.view(), b.view());
    // Frame b sees one column less of a's ground: 7 of 8 columns, every row.
    EXPECT_EQ(still.compared, 56u);
    EXPECT_EQ(still.changed, 0u);

    // An edge at a fixed image column (it moves with the camera): one column of points
    // changes state.
    const auto movingEdge = [](double, int column) { return column < 4; };
    const truth::ShimmerCount moving =
        truth::shimmerBetween(groundFrame(0.0, movingEdge).view(), groundFrame(1.0, movingEdge).view());
    EXPECT_EQ(moving.compared, 56u);
    EXPECT_EQ(moving.changed, 8u);
    EXPECT_DOUBLE_EQ(moving.fraction(), 8.0 / 56.0);
}

TEST(Shimmer, OnlyPointsLandingOnAPixelCentreWithTheSameTruthAreCompared) {
    const auto lit = [](double, int) { return false; };
    // Half a pixel sideways: no point lands within 0.1 pixel of a centre.
    EXPECT_EQ(truth::shimmerBetween(groundFrame(0.0, lit).view(), groundFrame(0.5, lit).view()).compared, 0u);
    // A point whose truth differs between the frames is not compared (the truth moved).
    Frame a = groundFrame(0.0, lit), b = groundFrame(1.0, lit);
    for (std::uint8_t& value : b.truth) value = 0;
    EXPECT_EQ(truth::shimmerBetween(a.view(), b.view()).compared, 0u);
    // Nor one outside either frame's evaluation set, nor one another instance covers.
    b = groundFrame(1.0, lit);
    for (std::uint8_t& value : b.evaluated) value = 0;
    EXPECT_EQ(truth::shimmerBetween(a.view(), b.view()).compared, 0u);
    b = groundFrame(1.0, lit);
    for (std::int32_t& instance : b.surfaces.instance) instance = 1;
    EXPECT_EQ(truth::shimmerBetween(a.view(), b.view()).compared, 0u);
}

} // namespace
