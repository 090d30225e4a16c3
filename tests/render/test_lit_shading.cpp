// Headless render tests of the lit pass (no plugin): a plane facing the camera and a
// sphere, lit by known lights, against the glTF 2.0 metallic-roughness BRDF (Appendix B)
// evaluated here in double (tests/support/MetallicRoughnessBrdf.h).
// The scenes, formulas and tolerance are in LitShadingFixture.h.
#include "LitShadingFixture.h"

#include <cstdint>

using namespace engine::test::lit;


TEST_F(LitShading, DirectionalLightMatchesFormula) {
    engine::Scene scene = planeScene(1.0f);
    addLight(scene, engine::Light::Type::Directional, {0, 0, 5}, 1.5f);
    EXPECT_LE(maxError(scene, 1.0), 2.0);
}

TEST_F(LitShading, PointLightWithAttenuationAndHighlightMatchesFormula) {
    engine::Scene scene = planeScene(0.5f);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 3.0f);
    EXPECT_LE(maxError(scene, 0.5), 2.0);
}

TEST_F(LitShading, MetallicPlaneHighlightMatchesFormula) {
    // A half-metal, fairly smooth plane: the colored f0, the (1 - F)(1 - metallic) diffuse
    // weight and the narrow GGX lobe with its long tail all show in one highlight.
    engine::Scene scene = planeScene(0.3f, 0.5f);
    scene.materials[0].baseColorFactor = glm::vec4(0.9f, 0.6f, 0.2f, 1.0f);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 3.0f);
    EXPECT_LE(maxError(scene, 0.3, [](const glm::dvec3&) { return glm::dvec3(0.9, 0.6, 0.2); }, nullptr, 0.5), 2.0);
}

TEST_F(LitShading, RoughDielectricSphereMatchesFormula) {
    // Every N.L and N.V on the lit side, from the terminator to head-on, and Fresnel rising
    // toward the rim where N.V is small.
    engine::Scene scene = planeScene(0.8f, 0.0f);
    scene.materials[0].baseColorFactor = glm::vec4(0.3f, 0.5f, 0.7f, 1.0f);
    addDirectionalLightFrom(scene, {1.0, 1.5, 2.0}, 2.5f);
    EXPECT_LE(sphereMaxError(scene, 0.7), 2.0);
}

TEST_F(LitShading, SmoothMetalSphereMatchesFormula) {
    // Metallic 1: no diffuse at all, a specular highlight in the base color.
    engine::Scene scene = planeScene(0.35f, 1.0f);
    scene.materials[0].baseColorFactor = glm::vec4(0.95f, 0.64f, 0.54f, 1.0f);
    addDirectionalLightFrom(scene, {-1.0, 0.8, 2.5}, 2.0f);
    EXPECT_LE(sphereMaxError(scene, 0.7), 2.0);
}

TEST_F(LitShading, MixedLightTypesEachShadeByTheirOwnType) {
    // Each light's type is compiled into the shader by slot (FOR_EACH_LIGHT): a spot, a point
    // and a directional light in one scene, every slot a different type, so shading a slot
    // as another's type (spot cone on the point, distance on the directional) fails.
    engine::Scene scene = planeScene(0.5f);
    addLight(scene, engine::Light::Type::Spot, {-0.5, 0.5, 2.0}, 2.0f, 0.5, 0.2);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 1.0f);
    addLight(scene, engine::Light::Type::Directional, {0, 0, 5}, 0.4f);
    EXPECT_LE(maxError(scene, 0.5), 2.0);
}

TEST_F(LitShading, TexturedAndUntexturedMaterialsInOneFrame) {
    // Textured primitives are drawn with their own program variant: both variants in one
    // pass, each half against the formula with its own albedo (the texel decoded from sRGB).
    engine::Scene scene = planeScene(0.5f);
    const glm::u8vec4 texel{200, 90, 40, 255};
    texturedLeftHalf(scene, texel);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 1.5f);
    const glm::dvec3 textured(srgbDecode(texel.r / 255.0), srgbDecode(texel.g / 255.0), srgbDecode(texel.b / 255.0));
    EXPECT_LE(maxError(scene, 0.5, [&](const glm::dvec3& p) { return p.x < 0.0 ? textured : kAlbedo; }), 2.0);
}

TEST_F(LitShading, AlphaMaskedMaterialsDiscardBelowTheirCutoff) {
    // Only alpha-masked materials' program variants can discard. The textured left half is
    // masked with a texel alpha under its cutoff: nothing drawn there. The right half is
    // masked too, untextured, its alpha above the cutoff: shaded by the formula.
    engine::Scene scene = planeScene(0.5f);
    texturedLeftHalf(scene, {200, 90, 40, 40});
    for (engine::Material& material : scene.materials) {
        material.alphaMode = engine::AlphaMode::Mask;
        material.alphaCutoff = 0.5f;
    }
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 1.5f);
    EXPECT_LE(maxError(scene, 0.5, nullptr, [](const glm::dvec3& p) { return p.x < 0.0; }), 2.0);
    // The same texel with the cutoff under its alpha is drawn.
    scene.materials[1].alphaCutoff = 0.1f;
    const glm::dvec3 textured(srgbDecode(200 / 255.0), srgbDecode(90 / 255.0), srgbDecode(40 / 255.0));
    EXPECT_LE(maxError(scene, 0.5, [&](const glm::dvec3& p) { return p.x < 0.0 ? textured : kAlbedo; }), 2.0);
}

TEST_F(LitShading, VertexColorsMultiplyTheBaseColor) {
    // COLOR_0 (linear) times the factor: a constant vertex color on the left half only, so
    // a variant that ignored it, or applied it to the right half too, fails.
    engine::Scene scene = planeScene(0.5f);
    texturedLeftHalf(scene, {255, 255, 255, 255});  // a white texel: the color alone counts
    const glm::vec4 vertexColor(0.5f, 0.25f, 0.9f, 1.0f);
    scene.meshes[0].primitives[0].colors.assign(4, vertexColor);
    scene.materials[1].baseColorFactor = glm::vec4(0.8f, 0.6f, 0.5f, 1.0f);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 1.5f);
    const glm::dvec3 left = glm::dvec3(0.8, 0.6, 0.5) * glm::dvec3(vertexColor);
    EXPECT_LE(maxError(scene, 0.5, [&](const glm::dvec3& p) { return p.x < 0.0 ? left : kAlbedo; }), 2.0);
}

TEST_F(LitShading, NoLightsRendersAmbientOnly) {
    engine::Scene scene = planeScene(0.5f);
    const auto pixels = render(scene);
    const glm::dvec3 ambient = kAmbient * kAlbedo;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pixels[(kSize / 2 * kSize + kSize / 2) * 4 + c], 255.0 * srgbEncode(ambient[c]), 1.0);
    // The plane covers the whole view: every pixel has the same ambient colour.
    for (int i = 0; i < kSize * kSize; ++i)
        ASSERT_EQ(pixels[i * 4 + 1], pixels[(kSize / 2 * kSize + kSize / 2) * 4 + 1]) << "pixel " << i;
}

TEST_F(LitShading, SrgbTextureThroughLinearShadingRoundTrips) {
    // The linear workflow end to end: a base color texture stored sRGB (GL_SRGB8_ALPHA8,
    // decoded on sampling), shaded in linear (ambient 1, no light: color = base color) and
    // encoded again by the sRGB target must give back every texel byte. A 16 x 16 texture
    // holds all 256 values in each channel (red row-major, green reversed, blue
    // scrambled); nearest filtering, and only pixels whose centre lies in a texel's middle
    // half, so no two texels mix. Tolerance 0: measured 0 on llvmpipe; an 8-bit value
    // decoded to float and encoded back lands on itself unless a step is lost, and a
    // missing decode or encode moves mid-grey by ~50 values.
    constexpr int kTexels = 16;
    constexpr double kHalf = 0.9;  // the quad spans 0.9 / 0.928 of the view: ~2.9 pixels a texel
    engine::Scene scene = planeScene(1.0f);
    scene.meshes[0].primitives = {engine::texturedQuadPrimitive({-kHalf, -kHalf}, {kHalf, kHalf}, 0)};
    scene.meshes[0].bounds = scene.meshes[0].primitives[0].bounds;
    engine::Image image;
    image.width = image.height = kTexels;
    const auto texelValue = [](int index, int channel) {
        return static_cast<std::uint8_t>(channel == 0 ? index : channel == 1 ? 255 - index : (index * 7 + 3) % 256);
    };
    for (int index = 0; index < kTexels * kTexels; ++index)
        image.rgba8.insert(image.rgba8.end(), {texelValue(index, 0), texelValue(index, 1), texelValue(index, 2), 255});
    scene.images.push_back(image);
    engine::Material& material = scene.materials[0];
    material.baseColorFactor = glm::vec4(1.0f);
    material.baseColorTexture.image = 0;
    material.baseColorTexture.sampler.minFilter = material.baseColorTexture.sampler.magFilter = 0x2600;  // GL_NEAREST
    const auto pixels = render(scene, glm::dvec3(1.0));

    std::vector<bool> seen(kTexels * kTexels, false);
    int worst = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = surfacePoint(camera(), x, y);
            // glTF UVs: v grows downward, image row 0 on top.
            const glm::dvec2 texel = glm::dvec2(p.x + kHalf, kHalf - p.y) / (2.0 * kHalf) * double(kTexels);
            const glm::dvec2 within = texel - glm::floor(texel);
            if (glm::any(glm::lessThan(texel, glm::dvec2(0.0))) ||
                glm::any(glm::greaterThanEqual(texel, glm::dvec2(kTexels))) ||
                glm::any(glm::greaterThan(glm::abs(within - 0.5), glm::dvec2(0.25))))
                continue;
            const int index = int(texel.y) * kTexels + int(texel.x);
            seen[index] = true;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(int(pixels[(y * kSize + x) * 4 + c]) - int(texelValue(index, c))));
        }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), kTexels * kTexels) << "every texel checked";
    EXPECT_EQ(worst, 0);
}

TEST_F(LitShading, EmissiveAddsToAmbientWithoutLights) {
    // color = emissive + ambient x base color. The emissive factor is above 1 in one
    // channel, as KHR_materials_emissive_strength allows (the loader folds the strength
    // in): that channel clamps to white. Tolerance 1/255: 8-bit rounding of the encode.
    engine::Scene scene = planeScene(0.5f);
    scene.materials[0].emissiveFactor = glm::vec3(0.3f, 0.05f, 2.0f);
    const auto pixels = render(scene);
    const glm::dvec3 expected = glm::dvec3(0.3, 0.05, 2.0) + kAmbient * kAlbedo;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pixels[(kSize / 2 * kSize + kSize / 2) * 4 + c], 255.0 * srgbEncode(expected[c]), 1.0) << "channel " << c;
}

TEST_F(LitShading, ExposureScalesTheRadianceBeforeTheEncode) {
    // A light 8x too bright for display units, brought back by exposure 1/8: the picture
    // matches the formula times 1/8 (and differs from exposure 1 by far more than 2/255).
    engine::Scene scene = planeScene(0.5f);
    scene.materials[0].emissiveFactor = glm::vec3(0.4f, 0.0f, 0.0f);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 24.0f);
    rendererConfig.exposure = 0.125f;
    EXPECT_LE(maxSurfaceError(scene, [](const glm::dvec3&) { return Surface{kAlbedo, 0.0, 0.5, {0, 0, 1}, 1.0, {0.4, 0, 0}}; }),
              2.0);
}

TEST_F(LitShading, PbrNeutralToneMappingCompressesHighlightsOnly) {
    // Khronos PBR Neutral against its formula in double: a point light whose highlight
    // exceeds 1 (compressed and desaturated toward white) over a dim surround (passed
    // through but for the black-level offset). Without tone mapping the highlight clips.
    engine::Scene scene = planeScene(0.3f, 0.5f);
    scene.materials[0].baseColorFactor = glm::vec4(0.9f, 0.6f, 0.2f, 1.0f);
    addLight(scene, engine::Light::Type::Point, {0.4, -0.3, 1.5}, 6.0f);
    rendererConfig.toneMapping = engine::RendererConfig::ToneMapping::PbrNeutral;
    const auto surface = [](const glm::dvec3&) { return Surface{{0.9, 0.6, 0.2}, 0.5, 0.3}; };
    EXPECT_LE(maxSurfaceError(scene, surface), 2.0);
    rendererConfig.toneMapping = engine::RendererConfig::ToneMapping::None;
    const std::vector<std::uint8_t> clipped = render(scene);
    rendererConfig.toneMapping = engine::RendererConfig::ToneMapping::PbrNeutral;
    EXPECT_NE(clipped, render(scene));
}
