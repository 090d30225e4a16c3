// loadGltf on the glTF features the alpha-tested shadows need: the base color texture's
// sampler, UV set and KHR_texture_transform, TEXCOORD_1, COLOR_0, KHR_lights_shadows on
// primitives and lights, and the material extras "shadow_alpha_cutoff"; each as written
// and with its defaults. Refusals of bad values are rows of test_gltf_bad_input.cpp.
#include "engine/gltf/GltfLoader.h"

#include "gltf_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace {

using namespace gltf_test;

json& firstPrimitive(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// Normalized 16-bit UVs for the quad's four vertices.
int addNormalizedUv(GltfBuilder& b, const std::vector<std::uint16_t>& uv) {
    return b.addAccessor(b.addView(uv.data(), uv.size() * 2), kUnsignedShort, 4, "VEC2", /*normalized=*/true);
}

// The quad with material 'leaf' whose baseColorTexture is `textureInfo` (index 0 added),
// texture 0 of a tiny PNG image stored in the buffer, sampled with `samplers[textureSampler]`.
GltfBuilder texturedQuad(json textureInfo, const json& samplers = nullptr, int textureSampler = -1) {
    GltfBuilder b = quadScene();
    const std::vector<std::uint8_t>& png = tinyPng();
    b.doc["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
    textureInfo["index"] = 0;
    json texture = {{"source", 0}};
    if (textureSampler >= 0) texture["sampler"] = textureSampler;
    b.doc["textures"] = {texture};
    if (!samplers.is_null()) b.doc["samplers"] = samplers;
    b.doc["materials"] = {{{"name", "leaf"}, {"pbrMetallicRoughness", {{"baseColorTexture", textureInfo}}}}};
    firstPrimitive(b)["material"] = 0;
    return b;
}

TEST(GltfTextures, ReadsSamplerTexCoordAndTextureTransform) {
    TempDir dir;
    const json transform = {{"offset", {0.25, -0.5}}, {"rotation", 1.5}, {"scale", {2, 3}}, {"texCoord", 1}};
    GltfBuilder b = texturedQuad({{"texCoord", 0}, {"extensions", {{"KHR_texture_transform", transform}}}},
                                 {{{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}}}, 0);
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    b.doc["extensionsRequired"] = {"KHR_texture_transform"};
    firstPrimitive(b)["attributes"]["TEXCOORD_1"] = addNormalizedUv(b, {0, 0, 65535, 0, 65535, 65535, 0, 65535});
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "transform"), &warnings);

    const engine::TextureRef& ref = scene.materials[0].baseColorTexture;
    EXPECT_EQ(ref.sampler.magFilter, 9728);
    EXPECT_EQ(ref.sampler.minFilter, 9984);
    EXPECT_EQ(ref.sampler.wrapS, 33071);
    EXPECT_EQ(ref.sampler.wrapT, 33648);
    EXPECT_EQ(ref.texCoord, 1);  // the extension's texCoord overrides the textureInfo's
    EXPECT_EQ(ref.transform.offset, glm::vec2(0.25f, -0.5f));
    EXPECT_EQ(ref.transform.rotation, 1.5f);
    EXPECT_EQ(ref.transform.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(scene.meshes[0].primitives[0].texcoords1[2], glm::vec2(1.0f, 1.0f));
    EXPECT_FALSE(mentions(warnings, "KHR_texture_transform")) << "a supported extension is not warned about";
    EXPECT_FALSE(mentions(warnings, "TEXCOORD")) << "the UV set the texture samples is there";
}

TEST(GltfTextures, EveryLegalSamplerEnumerantLoads) {
    TempDir dir;
    const json samplers = {{{"magFilter", 9729}, {"minFilter", 9728}, {"wrapS", 10497}, {"wrapT", 33071}},
                           {{"minFilter", 9729}},
                           {{"minFilter", 9985}},
                           {{"minFilter", 9986}},
                           {{"minFilter", 9987}}};
    for (int s = 0; s < 5; ++s) {
        const std::string name = std::to_string(s) + "-sampler";
        const engine::Sampler sampler =
            engine::loadGltf(texturedQuad(json::object(), samplers, s).writeGltf(dir.path(), name))
                .materials[0].baseColorTexture.sampler;
        EXPECT_EQ(sampler.minFilter, samplers[s]["minFilter"].get<int>());
    }
}

TEST(GltfTextures, DefaultsWhenSamplerTexCoordAndTransformAreAbsent) {
    TempDir dir;
    const engine::Sampler defaults;
    // No sampler on the texture; an empty sampler; a sampler writing tinygltf's "undefined".
    const engine::TextureRef none = engine::loadGltf(texturedQuad(json::object()).writeGltf(dir.path(), "none"))
                                        .materials[0].baseColorTexture;
    EXPECT_EQ(none.sampler, defaults);
    EXPECT_EQ(none.texCoord, 0);
    EXPECT_EQ(none.transform, engine::UvTransform{});
    EXPECT_EQ(engine::loadGltf(texturedQuad(json::object(), json::array({json::object()}), 0).writeGltf(dir.path(), "empty"))
                  .materials[0].baseColorTexture.sampler,
              defaults);
    const json undefined = {{{"magFilter", -1}, {"minFilter", -1}}};
    EXPECT_EQ(engine::loadGltf(texturedQuad(json::object(), undefined, 0).writeGltf(dir.path(), "undefined"))
                  .materials[0].baseColorTexture.sampler,
              defaults);
    // An empty transform is the identity.
    const engine::TextureRef identity =
        engine::loadGltf(texturedQuad({{"extensions", {{"KHR_texture_transform", json::object()}}}})
                             .writeGltf(dir.path(), "identity"))
            .materials[0].baseColorTexture;
    EXPECT_EQ(identity.transform, engine::UvTransform{});
    EXPECT_EQ(identity.transform.apply({0.3f, 0.7f}), glm::vec2(0.3f, 0.7f));
    // A material without texture.
    GltfBuilder plain = quadScene();
    plain.doc["materials"] = {json::object()};
    const engine::Material material = engine::loadGltf(plain.writeGltf(dir.path(), "plain")).materials[0];
    EXPECT_FALSE(material.baseColorTexture.present());
    EXPECT_EQ(material.blendShadowCutoff, 0.5f);
}

TEST(GltfTextures, UvSetAboveOneFallsBackToZeroWithAWarning) {
    TempDir dir;
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(texturedQuad({{"texCoord", 2}}).writeGltf(dir.path(), "set2"), &warnings);
    EXPECT_EQ(scene.materials[0].baseColorTexture.texCoord, 0);
    EXPECT_TRUE(mentions(warnings, "materials[0] 'leaf': pbrMetallicRoughness.baseColorTexture.texCoord 2 is not drawn"));

    warnings.clear();
    const json transform = {{"KHR_texture_transform", {{"texCoord", 3}}}};
    const engine::Scene viaTransform = engine::loadGltf(
        texturedQuad({{"texCoord", 1}, {"extensions", transform}}).writeGltf(dir.path(), "set3"), &warnings);
    EXPECT_EQ(viaTransform.materials[0].baseColorTexture.texCoord, 0);
    EXPECT_TRUE(mentions(warnings, "baseColorTexture.extensions.KHR_texture_transform.texCoord 3 is not drawn"));
}

TEST(GltfTextures, UnknownTextureTransformPropertyIsWarnedAbout) {
    TempDir dir;
    std::vector<std::string> warnings;
    const json transform = {{"KHR_texture_transform", {{"rotation", 0.5}, {"rotate", 1}}}};
    const engine::Scene scene =
        engine::loadGltf(texturedQuad({{"extensions", transform}}).writeGltf(dir.path(), "typo"), &warnings);
    EXPECT_EQ(scene.materials[0].baseColorTexture.transform.rotation, 0.5f);
    EXPECT_TRUE(mentions(warnings, "materials[0] 'leaf': unknown property "
                                   "'pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.rotate' is ignored"));
}

TEST(GltfTextures, PrimitiveLackingTheSampledUvSetIsWarnedAbout) {
    TempDir dir;
    std::vector<std::string> warnings;
    engine::loadGltf(texturedQuad({{"texCoord", 1}}).writeGltf(dir.path(), "noset1"), &warnings);
    EXPECT_TRUE(mentions(warnings, "meshes[0].primitives[0]: has no TEXCOORD_1, which the baseColorTexture of "
                                   "materials[0] 'leaf' samples"));
    warnings.clear();
    engine::loadGltf(texturedQuad(json::object()).writeGltf(dir.path(), "noset0"), &warnings);
    EXPECT_TRUE(mentions(warnings, "meshes[0].primitives[0]: has no TEXCOORD_0, which the baseColorTexture of "
                                   "materials[0] 'leaf' samples"));
    // With the set present: no such warning.
    warnings.clear();
    GltfBuilder b = texturedQuad(json::object());
    firstPrimitive(b)["attributes"]["TEXCOORD_0"] = addNormalizedUv(b, {0, 0, 1, 0, 1, 1, 0, 1});
    engine::loadGltf(b.writeGltf(dir.path(), "set0"), &warnings);
    EXPECT_FALSE(mentions(warnings, "TEXCOORD"));
}

TEST(GltfMaterials, ReadsShadowAlphaCutoffOfBlendMaterialsAndLeavesOtherExtrasAlone) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["materials"] = {{{"name", "glass"}, {"alphaMode", "BLEND"},
                           {"extras", {{"shadow_alpha_cutoff", 0.2}, {"author", "someone"}}}},
                          {{"name", "pane"}, {"alphaMode", "BLEND"}},
                          {{"name", "wall"}, {"extras", {{"author", "someone else"}}}},
                          {{"name", "never"}, {"alphaMode", "BLEND"}, {"extras", {{"shadow_alpha_cutoff", 2}}}}};
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "cutoff"));
    EXPECT_EQ(scene.materials[0].blendShadowCutoff, 0.2f);
    EXPECT_EQ(scene.materials[1].blendShadowCutoff, 0.5f);
    EXPECT_EQ(scene.materials[2].blendShadowCutoff, 0.5f);
    EXPECT_EQ(scene.materials[3].blendShadowCutoff, 2.0f);  // above 1: casts nothing
}

TEST(GltfMeshes, ReadsNormalizedTexcoord1) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const std::vector<std::uint8_t> uv{0, 0, 255, 0, 255, 255, 0, 128};
    firstPrimitive(b)["attributes"]["TEXCOORD_1"] = b.addAccessor(b.addView(uv.data(), uv.size()), kUnsignedByte, 4,
                                                                  "VEC2", /*normalized=*/true);
    const engine::Primitive p = engine::loadGltf(b.writeGltf(dir.path(), "uv1")).meshes[0].primitives[0];
    EXPECT_TRUE(p.texcoords.empty());
    ASSERT_EQ(p.texcoords1.size(), 4u);
    EXPECT_EQ(p.texcoords1[2], glm::vec2(1.0f, 1.0f));
    EXPECT_NEAR(p.texcoords1[3].y, 128.0f / 255.0f, 1e-7f);
}

TEST(GltfMeshes, ReadsColor0AsRgba) {
    TempDir dir;
    const auto load = [&](const std::string& name, const std::function<int(GltfBuilder&)>& addColors) {
        GltfBuilder b = quadScene();
        firstPrimitive(b)["attributes"]["COLOR_0"] = addColors(b);
        return engine::loadGltf(b.writeGltf(dir.path(), name)).meshes[0].primitives[0].colors;
    };
    const std::vector<glm::vec4> floatRgb = load("rgb", [](GltfBuilder& b) {
        return b.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5f, 0.5f, 0.5f}, 3, "VEC3");
    });
    EXPECT_EQ(floatRgb, (std::vector<glm::vec4>{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0.5f, 0.5f, 0.5f, 1}}));

    const std::vector<glm::vec4> byteRgba = load("rgba8", [](GltfBuilder& b) {
        const std::vector<std::uint8_t> rgba{255, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255, 51, 255, 255, 255, 255};
        return b.addAccessor(b.addView(rgba.data(), rgba.size()), kUnsignedByte, 4, "VEC4", true);
    });
    ASSERT_EQ(byteRgba.size(), 4u);
    EXPECT_EQ(byteRgba[1], glm::vec4(0, 1, 0, 0));
    EXPECT_NEAR(byteRgba[2].a, 0.2f, 1e-7f);

    const std::vector<glm::vec4> shortRgb = load("rgb16", [](GltfBuilder& b) {
        const std::vector<std::uint16_t> rgb{65535, 0, 0, 0, 65535, 0, 0, 0, 65535, 0, 0, 0};
        return b.addAccessor(b.addView(rgb.data(), rgb.size() * 2), kUnsignedShort, 4, "VEC3", true);
    });
    EXPECT_EQ(shortRgb, (std::vector<glm::vec4>{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0, 0, 0, 1}}));

    // Absent: empty (the renderer draws white).
    EXPECT_TRUE(engine::loadGltf(quadScene().writeGltf(dir.path(), "plain")).meshes[0].primitives[0].colors.empty());
}

TEST(GltfShadows, ReadsKhrLightsShadowsOnPrimitivesAndLights) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_lights_shadows"};
    b.doc["extensionsRequired"] = {"KHR_lights_shadows"};
    json plain = firstPrimitive(b);
    firstPrimitive(b)["extensions"]["KHR_lights_shadows"] = {{"castShadows", false}};
    json receiver = plain;
    receiver["extensions"]["KHR_lights_shadows"] = {{"receiveShadows", false}, {"castShadows", true}};
    b.doc["meshes"][0]["primitives"].push_back(receiver);
    b.doc["meshes"][0]["primitives"].push_back(plain);
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "dark"}, {"type", "point"}, {"extensions", {{"KHR_lights_shadows", {{"castShadows", false}}}}}},
        {{"name", "caster"}, {"type", "point"}, {"extensions", {{"KHR_lights_shadows", json::object()}}}},
        {{"name", "plain"}, {"type", "point"}}};
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "shadows"), &warnings);

    const std::vector<engine::Primitive>& p = scene.meshes[0].primitives;
    ASSERT_EQ(p.size(), 3u);
    EXPECT_FALSE(p[0].castShadows);
    EXPECT_TRUE(p[0].receiveShadows);
    EXPECT_TRUE(p[1].castShadows);
    EXPECT_FALSE(p[1].receiveShadows);
    EXPECT_TRUE(p[2].castShadows);
    EXPECT_TRUE(p[2].receiveShadows);
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_FALSE(scene.lights[0].castShadows);
    EXPECT_TRUE(scene.lights[1].castShadows);
    EXPECT_TRUE(scene.lights[2].castShadows);
    EXPECT_FALSE(mentions(warnings, "KHR_lights_shadows"));
}

TEST(GltfShadows, UnknownKhrLightsShadowsPropertiesAreWarnedAbout) {
    TempDir dir;
    GltfBuilder b = quadScene();
    firstPrimitive(b)["extensions"]["KHR_lights_shadows"] = {{"castShadow", false}};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"extensions", {{"KHR_lights_shadows", {{"receiveShadows", false}}}}}}};
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "typos"), &warnings);
    EXPECT_TRUE(scene.meshes[0].primitives[0].castShadows);
    EXPECT_TRUE(mentions(warnings, "meshes[0].primitives[0]: unknown property 'extensions.KHR_lights_shadows.castShadow'"));
    // A light does not receive: receiveShadows there is unknown too.
    EXPECT_TRUE(mentions(warnings,
                         "KHR_lights_punctual.lights[0] 'sun': unknown property 'extensions.KHR_lights_shadows.receiveShadows'"));
}

} // namespace
