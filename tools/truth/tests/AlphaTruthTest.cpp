// The ray-traced truth sees alpha: shadow rays from floor points under the grille of
// tests/support/GrilleScene.h pass where its texels are clear and stop where they are
// opaque, as worked out analytically; and the CPU sampler (TextureAlpha.h) against values
// computed by hand for each wrap mode and filter. No GL: the floor points are given
// directly, not captured.
#include "truth/RayTracedVisibility.h"
#include "truth/TextureAlpha.h"

#include "../../../tests/support/GrilleScene.h"

#include <gtest/gtest.h>

#include <cmath>

namespace truth {
namespace {

using engine::test::Grille;
using engine::test::kGrilleY;
using engine::test::kHalf;
using engine::test::kTexels;

constexpr int kNearest = engine::test::kNearest, kLinear = engine::test::kLinear;
constexpr int kRepeat = engine::test::kRepeat, kClamp = engine::test::kClampToEdge,
              kMirrored = engine::test::kMirroredRepeat;
const glm::dvec3 kLight(0.3, 7.0, 0.2);  // a point light above the grille

engine::Scene grilleScene(const Grille& grille) {
    engine::test::SceneBuilder builder;
    engine::test::addGrille(builder, grille);
    builder.addLight("bulb", engine::Light::Type::Point, kLight, kLight - glm::dvec3(0, 1, 0));
    return builder.build();
}

// Floor points (y = 0, facing up) whose ray to the light crosses the grille's plane at the
// given plane points.
SurfaceBuffer floorPointsUnder(const std::vector<glm::dvec2>& planePoints) {
    SurfaceBuffer surfaces;
    surfaces.width = static_cast<int>(planePoints.size());
    surfaces.height = 1;
    surfaces.cameraPosition = glm::dvec3(0, 2, 0);
    for (const glm::dvec2& q : planePoints) {
        // From the light through (q.x, kGrilleY, q.y) down to y = 0.
        const glm::dvec3 through(q.x, kGrilleY, q.y);
        const glm::dvec3 p = kLight + (through - kLight) * (kLight.y / (kLight.y - kGrilleY));
        surfaces.worldPosition.push_back(p);
        surfaces.worldNormal.push_back({0, 1, 0});
        surfaces.covered.push_back(1);
        surfaces.instance.push_back(-1);
    }
    return surfaces;
}

// Plane points on a fine grid over the grille, those within `margin` (in texels) of a texel
// boundary left out: there a point may round either way.
std::vector<glm::dvec2> gridAwayFromTexelEdges(double margin) {
    std::vector<glm::dvec2> points;
    const double texel = 2.0 * kHalf / kTexels;
    for (double x = -kHalf + 0.013; x < kHalf; x += 0.037)
        for (double z = -kHalf + 0.011; z < kHalf; z += 0.041) {
            const double fx = (x + kHalf) / texel, fz = (z + kHalf) / texel;
            if (std::abs(fx - std::round(fx)) < margin || std::abs(fz - std::round(fz)) < margin) continue;
            points.push_back({x, z});
        }
    return points;
}

// The rays of `points` through `grille`: how many the truth gets wrong against the pattern.
int disagreements(const Grille& grille, const std::vector<glm::dvec2>& points, int* blocked = nullptr) {
    const engine::Scene scene = grilleScene(grille);
    const std::vector<std::uint8_t> visible = visibility(scene, 0, floorPointsUnder(points));
    int wrong = 0, shadowed = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const bool blocks = engine::test::grilleAlpha(grille, points[i].x, points[i].y) >= engine::test::grilleCutoff(grille);
        shadowed += blocks;
        wrong += visible[i] == (blocks ? 1 : 0);
    }
    if (blocked) *blocked = shadowed;
    return wrong;
}

} // namespace

TEST(AlphaTruth, ShadowRaysPassThroughClearTexelsOnly) {
    const auto points = gridAwayFromTexelEdges(0.01);
    int blocked = 0;
    EXPECT_EQ(disagreements(Grille{}, points, &blocked), 0);
    // Both outcomes occur in quantity: the pattern is about a third opaque.
    EXPECT_GT(blocked, static_cast<int>(points.size()) / 5);
    EXPECT_LT(blocked, static_cast<int>(points.size()) * 3 / 5);
}

TEST(AlphaTruth, WrapModesAndTransformMoveTheHoles) {
    const auto points = gridAwayFromTexelEdges(0.02);
    for (const int wrap : {kRepeat, kClamp, kMirrored}) {
        Grille grille;
        grille.wrap = wrap;
        grille.uvMin = {-0.75f, -0.5f};
        grille.uvMax = {1.25f, 1.75f};
        EXPECT_EQ(disagreements(grille, points), 0) << "wrap " << wrap;
    }
    Grille transformed;
    transformed.wrap = kRepeat;
    transformed.transform = {{0.25f, 0.5f}, 0.0f, {2.0f, 0.5f}};  // axis-aligned: texel edges stay on the grid
    EXPECT_EQ(disagreements(transformed, points), 0);
    Grille secondSet;
    secondSet.viaTexcoord1 = true;
    EXPECT_EQ(disagreements(secondSet, points), 0);
}

TEST(AlphaTruth, BlendCastsByItsShadowCutoffAndPrimitivesMayOptOut) {
    const auto points = gridAwayFromTexelEdges(0.01);
    Grille blend;
    blend.mode = engine::AlphaMode::Blend;
    blend.opaqueAlpha = 0.7f;
    blend.clearAlpha = 0.3f;
    EXPECT_EQ(disagreements(blend, points), 0);
    blend.blendShadowCutoff = 0.0f;  // as an opaque pane: every ray under the grille blocked
    int blocked = 0;
    EXPECT_EQ(disagreements(blend, points, &blocked), 0);
    EXPECT_EQ(blocked, static_cast<int>(points.size()));

    Grille notCasting;
    notCasting.castShadows = false;
    const std::vector<std::uint8_t> visible =
        visibility(grilleScene(notCasting), 0, floorPointsUnder(points));
    EXPECT_EQ(std::count(visible.begin(), visible.end(), 1), static_cast<long>(points.size()));
}

TEST(AlphaTruth, LinearMagnificationIsExactAtTexelCentres) {
    // Bilinear filtering of a binary alpha returns each texel's own value at its centre.
    std::vector<glm::dvec2> centres;
    const double texel = 2.0 * kHalf / kTexels;
    for (int row = 0; row < kTexels; ++row)
        for (int column = 0; column < kTexels; ++column)
            centres.push_back({-kHalf + (column + 0.5) * texel, -kHalf + (row + 0.5) * texel});
    Grille linear;
    linear.magFilter = kLinear;
    EXPECT_EQ(disagreements(linear, centres), 0);
}

TEST(TextureAlpha, SamplesAsOpenGLDefines) {
    // A 4 x 1 image with alphas 0, 64, 128, 255 (row 0 = top).
    engine::Image image;
    image.width = 4;
    image.height = 1;
    for (const std::uint8_t alpha : {0, 64, 128, 255}) image.rgba8.insert(image.rgba8.end(), {0, 0, 0, alpha});
    const auto at = [&](int mag, int wrap, double u) {
        return sampleAlpha(image, {mag, kNearest, wrap, wrap}, {u, 0.5});
    };
    // NEAREST: the texel containing u; wrap modes map u outside [0, 1].
    EXPECT_DOUBLE_EQ(at(kNearest, kRepeat, 0.30), 64 / 255.0);
    EXPECT_DOUBLE_EQ(at(kNearest, kRepeat, 1.30), 64 / 255.0);
    EXPECT_DOUBLE_EQ(at(kNearest, kRepeat, -0.20), 1.0);             // texel -1 -> 3
    EXPECT_DOUBLE_EQ(at(kNearest, kClamp, -0.20), 0.0);
    EXPECT_DOUBLE_EQ(at(kNearest, kClamp, 1.70), 1.0);
    EXPECT_DOUBLE_EQ(at(kNearest, kMirrored, 1.10), 1.0);            // texel 4 -> 3
    EXPECT_DOUBLE_EQ(at(kNearest, kMirrored, 1.30), 128 / 255.0);    // texel 5 -> 2
    EXPECT_DOUBLE_EQ(at(kNearest, kMirrored, -0.10), 0.0);           // texel -1 -> 0
    // LINEAR: between the centres at u = 0.375 (64) and 0.625 (128).
    EXPECT_NEAR(at(kLinear, kRepeat, 0.5), 96 / 255.0, 1e-12);
    EXPECT_NEAR(at(kLinear, kRepeat, 0.4375), (0.75 * 64 + 0.25 * 128) / 255.0, 1e-12);
    // At u = 0 REPEAT blends the last texel in, CLAMP_TO_EDGE the first with itself.
    EXPECT_NEAR(at(kLinear, kRepeat, 0.0), 127.5 / 255.0, 1e-12);
    EXPECT_NEAR(at(kLinear, kClamp, 0.0), 0.0, 1e-12);
}

} // namespace truth
