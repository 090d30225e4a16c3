// Light-space perspective shadow maps (projection "lispsm", math/LispsmWarp.h) on the
// outdoor street (tests/support/OutdoorScene.h), against analytic truth: one warped map
// must at least halve the error of one uniform map of the same resolution within 25 m of the
// camera, and not raise it over the whole visible ground; cascades "auto" keeps the one
// warped map; and warped cascades are no worse than cascades alone.
#include "../../gl/GlTestContext.h"
#include "OutdoorGroundErrors.h"

namespace {

using engine::test::OutdoorScene;

constexpr int kWidth = 480, kHeight = 270;
constexpr double kNearCamera = 25.0;  // metres: "near the camera", as the cascade tests
constexpr int kWithEdges = 0;         // compareFloorMask's edge radius: every pixel counts

class Lispsm : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 1024}}); }

    // The sun's mask with `shadow` settings against the analytic truth on the ground: within
    // kNearCamera of the camera, or everywhere visible; off edges (2 pixels) or with them.
    engine::test::MaskStats groundErrors(const nlohmann::json& shadow, bool nearOnly, int edgeRadius,
                                         engine::ShadowView* sun = nullptr) {
        const auto everywhere = [](const glm::dvec3&) { return true; };
        return engine::test::outdoorGroundErrors(
            plugins(), shadow, kWidth, kHeight,
            nearOnly ? engine::test::withinOfOutdoorCamera(kNearCamera) : everywhere, edgeRadius, sun);
    }
};

const nlohmann::json kUniform{{"cascades", 1}, {"projection", "uniform"}};
const nlohmann::json kWarped{{"cascades", 1}, {"projection", "lispsm"}};

TEST_F(Lispsm, HalvesTheNearCameraErrorOfOneUniformMap) {
    for (const int edges : {kWithEdges, 2}) {
        const auto uniform = groundErrors(kUniform, true, edges);
        engine::ShadowView sun;
        const auto warped = groundErrors(kWarped, true, edges, &sun);
        std::printf("within %.0f m, edge radius %d: uniform %.3f%% (%d acne, %d leak), lispsm %.3f%% (%d, %d) of %d\n",
                    kNearCamera, edges, 100 * uniform.wrongFraction(), uniform.acne, uniform.leak,
                    100 * warped.wrongFraction(), warped.acne, warped.leak, warped.evaluated);
        ASSERT_GT(uniform.evaluated, 5000);
        ASSERT_GT(uniform.truthShadowed, 300);  // the posts' shadows are in view
        EXPECT_STREQ(engine::mapKindName(sun), "2d");
        // Measured on llvmpipe (1024 maps, 480x270): with edges uniform 5.252 % (1172 acne,
        // 1793 leak of 56460), lispsm 0.129 % (42, 31); off edges 2.656 % against 0.000 %.
        // The issue asks for half; a warp that gained nothing (or a body fitted as a box,
        // 0.7x) fails it.
        EXPECT_LE(warped.wrongFraction(), uniform.wrongFraction() / 2.0) << "edge radius " << edges;
    }
}

TEST_F(Lispsm, DoesNotRaiseTheErrorOverTheWholeGround) {
    const auto uniform = groundErrors(kUniform, false, kWithEdges);
    const auto warped = groundErrors(kWarped, false, kWithEdges);
    std::printf("whole ground: uniform %.3f%%, lispsm %.3f%% of %d\n", 100 * uniform.wrongFraction(),
                100 * warped.wrongFraction(), warped.evaluated);
    // The far texels grow (LispsmWarpTest: 15x at 110 m); the near ones, which cover most
    // pixels, shrink more. Measured: uniform 5.117 %, lispsm 0.628 % (the acne far down the
    // street). The bound: no worse than the uniform map.
    EXPECT_LE(warped.wrongFraction(), uniform.wrongFraction());
}

TEST_F(Lispsm, AutoCascadesKeepOneWarpedMap) {
    engine::ShadowView sun;
    groundErrors({{"projection", "lispsm"}}, true, 2, &sun);
    EXPECT_STREQ(engine::mapKindName(sun), "2d");
    EXPECT_EQ(sun.layers.size(), 1u);
}

// Each cascade warped around its own slice: no worse than the same cascades uniform (stable,
// the default), near the camera and over the whole ground. Measured with edges (1024 maps,
// 480x270): 2 cascades 0.723 -> 0.110 % near, 1.143 -> 0.610 % whole; 4 cascades
// 0.351 -> 0.175 %, 0.819 -> 0.658 %.
TEST_F(Lispsm, WarpedCascadesAreNoWorseThanCascadesAlone) {
    for (const int count : {2, 4}) {
        for (const bool nearOnly : {true, false}) {
            const auto uniform = groundErrors({{"cascades", count}}, nearOnly, kWithEdges);
            engine::ShadowView sun;
            const auto warped = groundErrors({{"cascades", count}, {"projection", "lispsm"}}, nearOnly, kWithEdges, &sun);
            std::printf("%d cascades, %s: uniform %.3f%% (%d acne, %d leak), lispsm %.3f%% (%d, %d) of %d\n", count,
                        nearOnly ? "within 25 m" : "whole ground", 100 * uniform.wrongFraction(), uniform.acne,
                        uniform.leak, 100 * warped.wrongFraction(), warped.acne, warped.leak, warped.evaluated);
            EXPECT_STREQ(engine::mapKindName(sun), "cascades");
            EXPECT_EQ(sun.layers.size(), static_cast<std::size_t>(count));
            EXPECT_LE(warped.wrongFraction(), uniform.wrongFraction()) << count << " cascades";
        }
    }
}

// 2048 maps: a short first cascade warped hard put its warp's centre a metre behind the
// camera, where the street's 1 km ground passes, and its depth was rasterized with errors
// no offset covered (kSliceWarpNScale, WarpedView.h). Measured (640x360, edges included):
// 4 cascades uniform 0.526 %, warped 12.0 % with the centre at n_opt and 0.420 % at 2 n_opt;
// 2 log-split cascades 1.542 %, 40.2 % and 0.588 %.
class LispsmFine : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 2048}}); }
};

TEST_F(LispsmFine, AHardWarpedFirstCascadeHasNoAcneOnALargeGround) {
    const auto everywhere = [](const glm::dvec3&) { return true; };
    for (const nlohmann::json& cascades : {nlohmann::json{{"cascades", 4}},
                                           nlohmann::json{{"cascades", 2}, {"cascade_lambda", 1.0}}}) {
        nlohmann::json warped = cascades;
        warped["projection"] = "lispsm";
        const auto uniform = engine::test::outdoorGroundErrors(plugins(), cascades, 640, 360, everywhere, kWithEdges);
        const auto lispsm = engine::test::outdoorGroundErrors(plugins(), warped, 640, 360, everywhere, kWithEdges);
        std::printf("%s: uniform %.3f%% (%d acne), lispsm %.3f%% (%d acne) of %d\n", cascades.dump().c_str(),
                    100 * uniform.wrongFraction(), uniform.acne, 100 * lispsm.wrongFraction(), lispsm.acne,
                    lispsm.evaluated);
        EXPECT_LE(lispsm.wrongFraction(), uniform.wrongFraction()) << cascades.dump();
    }
}

}  // namespace
