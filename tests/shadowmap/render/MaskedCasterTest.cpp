// Alpha-tested casters against visibility computed here, analytically: a horizontal
// "grille" (one double-sided quad whose base color texture has a known pattern of opaque
// and transparent texels) over a closed floor slab, lit from above by each light type
// under each variant, and seen from a camera below the grille. A floor point is shadowed
// exactly when the ray to the light crosses the grille's plane inside the quad at a point
// whose alpha (worked out here from the pattern, the UVs, the wrap mode and the texture
// transform, with NEAREST magnification so texel edges are exact) reaches the cutoff.
//
// Tolerance: pixels within 2 px of an analytic shadow edge are left out (a map texel
// projects to ~1 px here and PCF blurs one more texel); of the rest at most 0.3% may
// disagree, the bound the opaque-box tests (ShadowMaskTest.cpp) hold. Measured on
// llvmpipe: 0 wrong pixels in every case here; with the masks ignored (every caster solid)
// the grille cases had 30-70% wrong.
#include "../../gl/GlTestContext.h"
#include "../../support/GrilleScene.h"
#include "AnalyticShadows.h"

#include <cmath>

namespace {

using engine::Light;
using engine::test::FloorTruth;
using engine::test::SceneBuilder;

constexpr int kWidth = 160, kHeight = 120;
const engine::Aabb kFloor{{-10, -0.2, -10}, {10, 0, 10}};
using engine::test::Grille;
using engine::test::kGrilleY;
using engine::test::kHalf;

// Below the grille, looking down at the floor it shadows (the grille itself out of view).
engine::FrameCamera camera() {
    return engine::test::cameraLooking({0.1, 2.9, 0.2}, {0.1, 0.0, 0.25}, kWidth, kHeight, 1.6);
}

struct LightSetup {
    const char* name;
    Light::Type type;
    glm::dvec3 position, target;
};
const LightSetup kSpot{"spot", Light::Type::Spot, {0.3, 7.0, 0.2}, {0.0, 0.0, 0.0}};
const LightSetup kSun{"sun", Light::Type::Directional, {-1.5, 6.0, -1.0}, {0.0, 0.0, 0.0}};
const LightSetup kBulb{"bulb", Light::Type::Point, {0.2, 5.0, 0.3}, {0.2, 0.0, 0.3}};

// Floor visibility from the grille alone: the camera sits below the grille, so nothing
// hides the floor from it.
engine::test::FloorTruthFunction grilleTruth(const Grille& grille, const engine::Scene& scene) {
    return [&grille, &scene](const engine::test::Ray&, double, const glm::dvec3& p) {
        const engine::LightInstance& light = scene.lightInstances[0];
        const bool directional = scene.lights[light.light].type == Light::Type::Directional;
        const glm::dvec3 toLight = directional ? -light.direction() : light.position() - p;
        const double s = (kGrilleY - p.y) / toLight.y;  // where the ray meets the grille's plane
        if (s <= 0.0 || (!directional && s >= 1.0)) return FloorTruth::Lit;
        const glm::dvec3 q = p + s * toLight;
        if (std::abs(q.x) > kHalf || std::abs(q.z) > kHalf) return FloorTruth::Lit;
        return engine::test::grilleAlpha(grille, q.x, q.z) >= engine::test::grilleCutoff(grille) ? FloorTruth::Shadowed : FloorTruth::Lit;
    };
}

class MaskedCaster : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 1024}}); }

    static engine::Scene scene(const Grille& grille, const LightSetup& light, const std::string& variant) {
        SceneBuilder builder;
        builder.addBox("floor", kFloor.min, kFloor.max);
        engine::test::addGrille(builder, grille);
        builder.addLight(light.name, light.type, light.position, light.target, {{"variant", variant}}, 0.75);
        return builder.build();
    }

    // Renders light 0's mask and compares the floor with the analytic grille shadow.
    static engine::test::MaskStats compare(const Grille& grille, const LightSetup& light,
                                           const std::string& variant = "standard") {
        const engine::Scene built = scene(grille, light, variant);
        const auto mask = engine::test::renderShadowMask(plugins(), built, camera(), 0);
        const engine::LightInstance& placed = built.lightInstances[0];
        const auto inside = [&](const glm::dvec3& p) {
            if (light.type != Light::Type::Spot) return true;
            return std::acos(glm::dot(glm::normalize(p - placed.position()), placed.direction())) < 0.75 - 0.03;
        };
        return engine::test::compareFloorMaskWith(mask, camera(), 0.0, 9.9, inside, grilleTruth(grille, built));
    }

    // The floor shows the grille's pattern: the bars' shadow and the holes' light both in
    // quantity (a solid slab, or no shadow at all, fails), and every evaluated pixel right.
    static void expectPattern(const Grille& grille, const LightSetup& light = kSpot,
                              const std::string& variant = "standard") {
        const auto result = compare(grille, light, variant);
        EXPECT_GT(result.truthShadowed, 2000);
        EXPECT_GT(result.truthLit, 2000);
        EXPECT_LE(result.wrongFraction(), 0.003);
    }
};

// Every light type under every variant.
class MaskedCasterVariants : public MaskedCaster,
                             public ::testing::WithParamInterface<std::tuple<const char*, LightSetup>> {};

} // namespace

TEST_P(MaskedCasterVariants, FloorShadowIsTheGrillePattern) {
    const auto& [variant, light] = GetParam();
    expectPattern(Grille{}, light, variant);
}

INSTANTIATE_TEST_SUITE_P(
    VariantsAndLights, MaskedCasterVariants,
    ::testing::Combine(::testing::Values("standard", "woo", "backface"), ::testing::Values(kSpot, kSun, kBulb)),
    [](const auto& info) {
        return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param).name;
    });

// Texture coordinates as glTF defines them: each wrap mode, over UVs reaching past [0, 1],
// puts the holes somewhere else (REPEAT tiles the pattern, MIRRORED_REPEAT mirrors it,
// CLAMP_TO_EDGE stretches its edge texels).
struct WrapCase {
    const char* name;
    int wrap;
    glm::vec2 uvMin, uvMax;
};

class MaskedCasterWrap : public MaskedCaster, public ::testing::WithParamInterface<WrapCase> {};

TEST_P(MaskedCasterWrap, HolesWhereTheWrapModePutsThem) {
    Grille grille;
    grille.wrap = GetParam().wrap;
    grille.uvMin = GetParam().uvMin;
    grille.uvMax = GetParam().uvMax;
    expectPattern(grille);
}

INSTANTIATE_TEST_SUITE_P(WrapModes, MaskedCasterWrap,
                         ::testing::Values(WrapCase{"repeat", engine::test::kRepeat, {-0.5f, 0.25f}, {1.5f, 2.0f}},
                                           WrapCase{"mirrored_repeat", engine::test::kMirroredRepeat, {-1.0f, -0.5f}, {1.0f, 1.25f}},
                                           WrapCase{"clamp_to_edge", engine::test::kClampToEdge, {-0.5f, -0.25f}, {1.5f, 1.25f}}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(MaskedCaster, TextureTransformMovesThePattern) {
    Grille grille;
    grille.wrap = engine::test::kRepeat;
    grille.transform.offset = {0.3f, -0.2f};
    grille.transform.scale = {1.5f, 0.75f};
    grille.transform.rotation = 0.5f;
    expectPattern(grille);
}

TEST_F(MaskedCaster, Texcoord1IsReadWhenTheMaterialSaysSo) {
    Grille grille;
    grille.viaTexcoord1 = true;
    expectPattern(grille);
}

TEST_F(MaskedCaster, VertexColorAlphaCutsTheCaster) {
    Grille grille;
    grille.vertexAlphaOnly = true;
    expectPattern(grille);
}

// BLEND: cast where alpha reaches the material's blendShadowCutoff (default 0.5).
TEST_F(MaskedCaster, BlendCastsWhereAlphaReachesItsShadowCutoff) {
    Grille grille;
    grille.mode = engine::AlphaMode::Blend;
    grille.opaqueAlpha = 0.7f;
    grille.clearAlpha = 0.3f;
    expectPattern(grille);

    grille.blendShadowCutoff = 0.0f;  // casts everywhere, as an opaque pane
    const auto solid = compare(grille, kSpot);
    EXPECT_GT(solid.truthShadowed, 5000);
    EXPECT_LE(solid.wrongFraction(), 0.003);

    grille.blendShadowCutoff = 0.8f;  // above every alpha: casts nothing
    const auto none = compare(grille, kSpot);
    EXPECT_EQ(none.truthShadowed, 0);
    EXPECT_GT(none.truthLit, 5000);
    EXPECT_EQ(none.wrong(), 0);
}

// KHR_lights_shadows: each flag alone turns the grille's shadow off.
TEST_F(MaskedCaster, LightsShadowsFlagsTurnTheShadowOff) {
    const auto shadowedPixels = [](const engine::Scene& scene) {
        const auto mask = engine::test::renderShadowMask(plugins(), scene, camera(), 0);
        return std::count_if(mask.begin(), mask.end(), [](std::uint8_t shade) { return shade < 128; });
    };
    const engine::Scene plain = scene(Grille{}, kSpot, "standard");
    ASSERT_GT(shadowedPixels(plain), 2000);  // the flags below have something to turn off

    engine::Scene lightOff = plain;
    lightOff.lights[0].castShadows = false;
    EXPECT_EQ(shadowedPixels(lightOff), 0);

    Grille notCasting;
    notCasting.castShadows = false;
    EXPECT_EQ(shadowedPixels(scene(notCasting, kSpot, "standard")), 0);

    engine::Scene floorNotReceiving = plain;
    for (engine::Primitive& primitive : floorNotReceiving.meshes[0].primitives) primitive.receiveShadows = false;
    EXPECT_EQ(shadowedPixels(floorNotReceiving), 0);
}
