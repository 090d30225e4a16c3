// The texel-density heat map (truth/TexelDensityImage.h): the documented colours at the
// scale's stops, log-scale interpolation between them, grey without a value; and the per-pixel
// m image on a hand-made capture. No GL.
#include "truth/TexelDensityImage.h"
#include "truth/TexelMetric.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

namespace {

using Rgba = std::array<std::uint8_t, 4>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

// The values docs/metrics.md and the overlay name: 0.5 (and below) blue, 1 green, 4 yellow,
// 16 (and above) red.
TEST(TexelDensityImage, GivesTheDocumentedColoursAtTheStops) {
    EXPECT_EQ(truth::texelDensityColor(0.5), (Rgba{0, 0, 255, 255}));
    EXPECT_EQ(truth::texelDensityColor(0.01), (Rgba{0, 0, 255, 255}));
    EXPECT_EQ(truth::texelDensityColor(1.0), (Rgba{0, 255, 0, 255}));
    EXPECT_EQ(truth::texelDensityColor(4.0), (Rgba{255, 255, 0, 255}));
    EXPECT_EQ(truth::texelDensityColor(16.0), (Rgba{255, 0, 0, 255}));
    EXPECT_EQ(truth::texelDensityColor(1e6), (Rgba{255, 0, 0, 255}));
}

// Half way in log2 between 1 and 4 is m = 2: half way from green to yellow (255 * 0.5 rounds
// to 128). Between 4 and 16, m = 8 is half way to red. m = 2^-0.75 is a quarter of the way
// from blue (0.5 = 2^-1) to green: 63.75 green, 191.25 blue.
TEST(TexelDensityImage, InterpolatesInLog2OfM) {
    EXPECT_EQ(truth::texelDensityColor(2.0), (Rgba{128, 255, 0, 255}));
    EXPECT_EQ(truth::texelDensityColor(8.0), (Rgba{255, 128, 0, 255}));
    EXPECT_EQ(truth::texelDensityColor(std::pow(2.0, -0.75)), (Rgba{0, 64, 191, 255}));
}

TEST(TexelDensityImage, IsGreyWithoutAValue) {
    const Rgba grey{128, 128, 128, 255};
    for (double m : {kNaN, std::numeric_limits<double>::infinity(), 0.0, -1.0})
        EXPECT_EQ(truth::texelDensityColor(m), grey) << m;
    const std::vector<double> image = {1.0, kNaN, 16.0};
    EXPECT_EQ(truth::texelDensityImage(image),
              (std::vector<std::uint8_t>{0, 255, 0, 255, 128, 128, 128, 255, 255, 0, 0, 255}));
}

TEST(TexelDensityImage, NamesTheScaleFromItsTable) {
    EXPECT_EQ(truth::texelDensityLegend(),
              "m (px per texel) <=0.5 blue, 1 green, 4 yellow, >=16 red, log scale; grey: no value");
}

// A 2-pixel capture of the ground y = 0 under a sun looking straight down: the evaluated
// pixel gets texelOnScreen's value, the pixel outside the evaluation set and every pixel of a
// view without a map have none.
TEST(TexelDensityImage, ComputesMOnlyWhereTheLookupHasALayer) {
    truth::SurfaceBuffer surfaces;
    surfaces.width = 2;
    surfaces.height = 1;
    surfaces.camera.eyeToWorld = glm::inverse(glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0), glm::dvec3(0, 0, -1)));
    surfaces.camera.projection = glm::perspective(glm::radians(60.0), 2.0, 0.1, 100.0);
    surfaces.camera.width = 2;
    surfaces.camera.height = 1;
    surfaces.worldPosition = {{1, 0, 1}, {-1, 0, 2}};
    surfaces.worldNormal = {{0, 1, 0}, {0, 1, 0}};
    surfaces.covered = {1, 1};

    engine::ShadowView view;
    view.hasMap = true;
    view.settings["resolution"] = 1024;
    engine::ShadowMapLayer layer;
    layer.rendered = true;
    layer.lightToWorld = glm::inverse(glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0), glm::dvec3(0, 0, -1)));
    layer.projection = glm::ortho(-8.0, 8.0, -8.0, 8.0, 0.1, 100.0);
    view.layers.push_back(layer);

    const std::vector<std::uint8_t> evaluated = {1, 0};
    const std::vector<double> m = truth::texelOnScreenImage(view, surfaces, evaluated);
    ASSERT_EQ(m.size(), 2u);
    EXPECT_DOUBLE_EQ(m[0], truth::texelOnScreen(surfaces.worldPosition[0], surfaces.worldNormal[0], surfaces.camera,
                                                layer.projection * glm::inverse(layer.lightToWorld), 1024));
    EXPECT_TRUE(std::isnan(m[1]));
    for (double value : truth::texelOnScreenImage(engine::ShadowView{}, surfaces, evaluated)) EXPECT_TRUE(std::isnan(value));
}
