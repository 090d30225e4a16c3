// Headless render tests of the material textures the lit pass samples beside the base
// color (glTF 2.0 section 3.9): metallicRoughnessTexture, normalTexture with its scale and
// the tangent frame, occlusionTexture with its strength, emissiveTexture. Each puts a
// one-texel texture on the left half of the analytic plane (LitShadingFixture.h) and checks
// every pixel of both halves against the Appendix B formulas evaluated in double with the
// texel's value, within the fixture's 2/255 (its comment says where that comes from). Each
// texel is chosen so that a wrong channel, a missing decode or a texture applied to the
// wrong term misses by far more than that (the figures are in each test).
#include "LitShadingFixture.h"

#include <cstdint>

using namespace engine::test::lit;

namespace {

double unorm(std::uint8_t value) { return value / 255.0; }

glm::dvec3 srgbDecoded(const glm::u8vec4& texel) {
    return {srgbDecode(unorm(texel.r)), srgbDecode(unorm(texel.g)), srgbDecode(unorm(texel.b))};
}

// The tangent-space normal a normal-map texel holds, scaled as glTF 2.0 section 3.9.3
// says: normalize((texel * 2 - 1) * (scale, scale, 1)).
glm::dvec3 tangentSpaceNormal(const glm::u8vec4& texel, double scale) {
    const glm::dvec3 decoded(unorm(texel.r) * 2.0 - 1.0, unorm(texel.g) * 2.0 - 1.0, unorm(texel.b) * 2.0 - 1.0);
    return glm::normalize(decoded * glm::dvec3(scale, scale, 1.0));
}

// The texel encoding the unit vector `normal` (x right, y up the image, z out of it).
glm::u8vec4 normalTexel(const glm::dvec3& normal) {
    const glm::dvec3 encoded = glm::round((glm::normalize(normal) + 1.0) * 0.5 * 255.0);
    return {static_cast<std::uint8_t>(encoded.x), static_cast<std::uint8_t>(encoded.y),
            static_cast<std::uint8_t>(encoded.z), 255};
}

bool onLeftHalf(const glm::dvec3& point) { return point.x < 0.0; }

} // namespace

TEST_F(LitShading, MetallicRoughnessTextureScalesTheFactors) {
    // Metalness from blue, roughness from green, each times its factor. Red is 255 and
    // alpha 255: a shader reading them (or linear values as sRGB) shades another surface.
    // The highlight sits on the left half, where the texture halves the roughness.
    engine::Scene scene = planeScene(0.8f, 0.9f);
    scene.materials[0].baseColorFactor = glm::vec4(0.9f, 0.6f, 0.2f, 1.0f);
    const glm::u8vec4 texel{255, 90, 150, 255};
    leftHalfWithTexture(scene, texel, &engine::Material::metallicRoughnessTexture);
    addLight(scene, engine::Light::Type::Point, {-0.8, -0.3, 1.5}, 3.0f);
    const glm::dvec3 baseColor(0.9, 0.6, 0.2);
    const auto surfaceAt = [&](const glm::dvec3& point) {
        if (!onLeftHalf(point)) return Surface{baseColor, 0.9, 0.8};
        return Surface{baseColor, 0.9 * unorm(texel.b), 0.8 * unorm(texel.g)};
    };
    EXPECT_LE(maxSurfaceError(scene, surfaceAt), 2.0);
    // The same picture against the factors alone misses: the texture did something.
    EXPECT_GT(maxSurfaceError(scene, [&](const glm::dvec3&) { return Surface{baseColor, 0.9, 0.8}; }), 10.0);
}

TEST_F(LitShading, NormalMapTiltsTheShadingNormal) {
    // A texel tilting the normal right and down the image: in the left half's tangent frame
    // (tangent +x, bitangent +y up the image, normal +z) the shading normal is the texel's
    // vector itself. One light from the upper right, one point light for a highlight: N.L,
    // N.V and N.H all follow the tilt.
    engine::Scene scene = planeScene(0.4f);
    const glm::u8vec4 texel = normalTexel({0.45, -0.3, 0.84});
    leftHalfWithTexture(scene, texel, &engine::Material::normalTexture);
    addDirectionalLightFrom(scene, {1.5, 1.0, 2.0}, 1.5f);
    addLight(scene, engine::Light::Type::Point, {-0.8, -0.3, 1.5}, 2.0f);
    for (const double scale : {1.0, 0.5}) {
        SCOPED_TRACE("normal scale " + std::to_string(scale));
        scene.materials[1].normalScale = static_cast<float>(scale);
        const glm::dvec3 tilted = tangentSpaceNormal(texel, scale);
        EXPECT_LE(maxSurfaceError(scene,
                                  [&](const glm::dvec3& point) {
                                      return Surface{kAlbedo, 0.0, 0.4, onLeftHalf(point) ? tilted : glm::dvec3(0, 0, 1)};
                                  }),
                  2.0);
    }
}

TEST_F(LitShading, NormalMapBitangentFollowsTheTangentSign) {
    // TANGENT's w mirrors the bitangent: with w = -1 the texel's "up" is down the image,
    // so the same texel tilts the normal toward -y instead. A shader ignoring w (or taking
    // the bitangent from the UVs' screen direction) fails.
    engine::Scene scene = planeScene(0.4f);
    const glm::u8vec4 texel = normalTexel({0.2, 0.5, 0.84});
    leftHalfWithTexture(scene, texel, &engine::Material::normalTexture);
    for (glm::vec4& tangent : scene.meshes[0].primitives[0].tangents) tangent.w = -1.0f;
    addDirectionalLightFrom(scene, {0.5, 2.0, 2.0}, 1.5f);
    const glm::dvec3 tilted = tangentSpaceNormal(texel, 1.0) * glm::dvec3(1.0, -1.0, 1.0);
    const auto surfaceWith = [&](const glm::dvec3& normal) {
        return [&, normal](const glm::dvec3& point) {
            return Surface{kAlbedo, 0.0, 0.4, onLeftHalf(point) ? normal : glm::dvec3(0, 0, 1)};
        };
    };
    EXPECT_LE(maxSurfaceError(scene, surfaceWith(tilted)), 2.0);
    EXPECT_GT(maxSurfaceError(scene, surfaceWith(tangentSpaceNormal(texel, 1.0))), 10.0);
}

TEST_F(LitShading, OcclusionTextureDimsOnlyTheAmbientTerm) {
    // ambient x base color x (1 + strength x (red - 1)); the light's terms untouched. Green
    // and blue are 255: a shader reading them sees no occlusion.
    engine::Scene scene = planeScene(0.6f);
    const glm::u8vec4 texel{60, 255, 255, 255};
    leftHalfWithTexture(scene, texel, &engine::Material::occlusionTexture);
    scene.materials[1].occlusionStrength = 0.7f;
    const double occlusion = 1.0 + 0.7 * (unorm(texel.r) - 1.0);
    const auto surfaceAt = [&](const glm::dvec3& point) {
        return Surface{kAlbedo, 0.0, 0.6, {0, 0, 1}, onLeftHalf(point) ? occlusion : 1.0};
    };
    // Ambient alone first (the occluded half is 16/255 darker), then with a light whose
    // terms must not be occluded.
    EXPECT_LE(maxSurfaceError(scene, surfaceAt), 2.0);
    EXPECT_GT(maxSurfaceError(scene, [](const glm::dvec3&) { return Surface{kAlbedo, 0.0, 0.6}; }), 10.0);
    addLight(scene, engine::Light::Type::Point, {-0.8, -0.3, 1.5}, 1.0f);
    EXPECT_LE(maxSurfaceError(scene, surfaceAt), 2.0);
}

TEST_F(LitShading, EmissiveTextureIsSrgbTimesTheFactor) {
    // emissive = factor x texel decoded from sRGB (linear 200/255 = 0.78 would read 0.58
    // decoded: 30/255 off). No light: emission plus ambient only.
    engine::Scene scene = planeScene(0.5f);
    const glm::vec3 factor(0.5f, 1.0f, 1.5f);
    scene.materials[0].emissiveFactor = factor;
    const glm::u8vec4 texel{200, 100, 50, 255};
    leftHalfWithTexture(scene, texel, &engine::Material::emissiveTexture);
    const glm::dvec3 emitted = glm::dvec3(factor) * srgbDecoded(texel);
    EXPECT_LE(maxSurfaceError(scene,
                              [&](const glm::dvec3& point) {
                                  return Surface{kAlbedo, 0.0, 0.5, {0, 0, 1}, 1.0,
                                                 onLeftHalf(point) ? emitted : glm::dvec3(factor)};
                              }),
              2.0);
}

TEST_F(LitShading, EveryTextureAtOnceOnOnePrimitive) {
    // The five textures in one program variant (each on its own unit, each with its own
    // UV set and transform): the left half samples TEXCOORD_1 for the normal map through a
    // transform that moves it onto the normal texel of a 2x1 image, the rest TEXCOORD_0.
    engine::Scene scene = planeScene(0.7f, 0.3f);
    scene.materials[0].emissiveFactor = glm::vec3(0.2f, 0.1f, 0.05f);
    const glm::u8vec4 base{220, 180, 90, 255}, metalRough{0, 120, 200, 255}, occlusion{128, 0, 0, 255},
        emissive{90, 200, 255, 255};
    const glm::u8vec4 normal = normalTexel({-0.35, 0.25, 0.9});
    leftHalfWithTexture(scene, base, &engine::Material::baseColorTexture);
    engine::Material& material = scene.materials[1];
    material.baseColorFactor = glm::vec4(1.0f);
    const auto addTexel = [&](const glm::u8vec4& texel, engine::TextureRef& slot) {
        engine::Image image;
        image.width = image.height = 1;
        image.rgba8 = {texel.r, texel.g, texel.b, texel.a};
        scene.images.push_back(image);
        slot.image = static_cast<int>(scene.images.size()) - 1;
    };
    addTexel(metalRough, material.metallicRoughnessTexture);
    addTexel(occlusion, material.occlusionTexture);
    addTexel(emissive, material.emissiveTexture);
    // The normal map: a 2x1 image, a wrong texel on the left and the normal on the right;
    // TEXCOORD_1 is (0, 0) everywhere and the transform's offset moves it to u = 0.75.
    engine::Image normalImage;
    normalImage.width = 2;
    normalImage.height = 1;
    normalImage.rgba8 = {128, 128, 0, 255, normal.r, normal.g, normal.b, 255};
    scene.images.push_back(normalImage);
    material.normalTexture.image = static_cast<int>(scene.images.size()) - 1;
    material.normalTexture.texCoord = 1;
    material.normalTexture.transform.offset = glm::vec2(0.75f, 0.5f);
    material.normalTexture.sampler.minFilter = material.normalTexture.sampler.magFilter = 0x2600;  // GL_NEAREST
    material.occlusionStrength = 1.0f;
    scene.meshes[0].primitives[0].texcoords1.assign(4, glm::vec2(0.0f));
    addLight(scene, engine::Light::Type::Point, {-0.8, 0.3, 1.5}, 2.5f);
    const Surface left{srgbDecoded(base),
                       0.3 * unorm(metalRough.b),
                       0.7 * unorm(metalRough.g),
                       tangentSpaceNormal(normal, 1.0),
                       unorm(occlusion.r),
                       glm::dvec3(0.2, 0.1, 0.05) * srgbDecoded(emissive)};
    EXPECT_LE(maxSurfaceError(scene,
                              [&](const glm::dvec3& point) {
                                  return onLeftHalf(point) ? left
                                                           : Surface{kAlbedo, 0.3, 0.7, {0, 0, 1}, 1.0, {0.2, 0.1, 0.05}};
                              }),
              2.0);
}
