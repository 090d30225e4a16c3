// loadGltf on the metallic-roughness material parts beyond the base color:
// KHR_materials_emissive_strength (a factor on the emissive color), and the
// metallic-roughness, normal, occlusion and emissive textures, each with its sampler, UV set
// and KHR_texture_transform, the normal texture's scale and the occlusion's strength.
// Refusals of bad values are rows of test_gltf_bad_input.cpp.
#include "engine/gltf/GltfLoader.h"

#include "gltf_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using namespace gltf_test;

int countMentioning(const std::vector<std::string>& warnings, const std::string& text) {
    return static_cast<int>(std::count_if(warnings.begin(), warnings.end(),
                                          [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

} // namespace

TEST(GltfPbrMaterials, EmissiveStrengthMultipliesTheEmissiveFactor) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    b.doc["materials"] = {
        {{"name", "lamp"}, {"emissiveFactor", {1.0, 0.5, 0.25}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
        {{"name", "plain"}, {"emissiveFactor", {0.2, 0.3, 0.4}}},
        // The extension without its member: strength 1, as the extension's default.
        {{"name", "default"}, {"emissiveFactor", {0.5, 0.5, 0.5}}, {"extensions", {{"KHR_materials_emissive_strength", json::object()}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "emissive"), &warnings);
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[0].emissiveFactor, glm::vec3(4.0f, 2.0f, 1.0f));
    EXPECT_EQ(scene.materials[1].emissiveFactor, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_EQ(scene.materials[2].emissiveFactor, glm::vec3(0.5f));
    // Read, so not reported as an unsupported extension.
    EXPECT_EQ(countMentioning(warnings, "KHR_materials_emissive_strength"), 0);
}

// Texture 0 (no sampler) and texture 1 (sampler 0) of one image; each material texture
// names one of them, its own UV set and transform, so a mix-up between them shows.
TEST(GltfPbrMaterials, EveryMaterialTextureIsReadWithItsSamplerUvSetAndTransform) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const std::vector<std::uint8_t>& png = tinyPng();
    b.doc["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
    b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}}};
    b.doc["textures"] = {{{"source", 0}}, {{"source", 0}, {"sampler", 0}}};
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    const json normalTransform = {{"offset", {0.25, 0.5}}, {"rotation", 0.75}, {"scale", {2, 3}}, {"texCoord", 1}};
    const json emissiveTransform = {{"rotation", -1.5}};
    b.doc["materials"] = {
        {{"name", "brick"},
         {"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 1}, {"texCoord", 1}}}}},
         {"normalTexture", {{"index", 0}, {"scale", -0.5}, {"extensions", {{"KHR_texture_transform", normalTransform}}}}},
         {"occlusionTexture", {{"index", 1}, {"strength", 0.25}}},
         {"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", emissiveTransform}}}}},
         {"emissiveFactor", {1.0, 0.5, 0.0}}},
        {{"name", "plain"}}};
    json& primitive = b.doc["meshes"][0]["primitives"][0];
    primitive["material"] = 0;
    primitive["attributes"]["TEXCOORD_0"] = b.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, 2, "VEC2");
    primitive["attributes"]["TEXCOORD_1"] = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, 2, "VEC2");
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "textures"), &warnings);
    ASSERT_EQ(scene.materials.size(), 2u);
    const engine::Material& brick = scene.materials[0];
    const engine::Sampler sampler0{9728, 9984, 33071, 33648};

    EXPECT_EQ(brick.metallicRoughnessTexture.image, 0);
    EXPECT_EQ(brick.metallicRoughnessTexture.texCoord, 1);
    EXPECT_EQ(brick.metallicRoughnessTexture.sampler, sampler0);
    EXPECT_EQ(brick.metallicRoughnessTexture.transform, engine::UvTransform{});

    EXPECT_EQ(brick.normalTexture.image, 0);
    EXPECT_EQ(brick.normalTexture.texCoord, 1) << "the transform's texCoord overrides the textureInfo's 0";
    EXPECT_EQ(brick.normalTexture.sampler, engine::Sampler{});
    EXPECT_EQ(brick.normalTexture.transform, (engine::UvTransform{{0.25f, 0.5f}, 0.75f, {2.0f, 3.0f}}));
    EXPECT_EQ(brick.normalScale, -0.5f);

    EXPECT_EQ(brick.occlusionTexture.image, 0);
    EXPECT_EQ(brick.occlusionTexture.texCoord, 0);
    EXPECT_EQ(brick.occlusionTexture.sampler, sampler0);
    EXPECT_EQ(brick.occlusionStrength, 0.25f);

    EXPECT_EQ(brick.emissiveTexture.image, 0);
    EXPECT_EQ(brick.emissiveTexture.texCoord, 0);
    EXPECT_EQ(brick.emissiveTexture.sampler, engine::Sampler{});
    EXPECT_EQ(brick.emissiveTexture.transform.rotation, -1.5f);
    EXPECT_EQ(brick.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));

    // Absent: no textures, and the scale and strength glTF defines as their defaults.
    const engine::Material& plain = scene.materials[1];
    for (const engine::TextureRef* texture : {&plain.metallicRoughnessTexture, &plain.normalTexture,
                                              &plain.occlusionTexture, &plain.emissiveTexture})
        EXPECT_FALSE(texture->present());
    EXPECT_EQ(plain.normalScale, 1.0f);
    EXPECT_EQ(plain.occlusionStrength, 1.0f);

    // Read, so not reported; every UV set they sample is there, so nothing else either.
    for (const std::string& warning : warnings) {
        EXPECT_EQ(warning.find("Texture"), std::string::npos) << warning;
        EXPECT_EQ(warning.find("TEXCOORD"), std::string::npos) << warning;
    }
}

// A primitive without the UV set a texture samples draws it at uv (0,0): one warning per
// texture, naming it (the normal texture's consequence is its own: test_gltf_tangents.cpp).
TEST(GltfPbrMaterials, EachTextureSamplingAMissingUvSetIsReported) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const std::vector<std::uint8_t>& png = tinyPng();
    b.doc["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"name", "stone"},
                           {"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 0}, {"texCoord", 1}}}}},
                           {"occlusionTexture", {{"index", 0}, {"texCoord", 1}}},
                           {"emissiveTexture", {{"index", 0}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, 2, "VEC2");
    std::vector<std::string> warnings;
    engine::loadGltf(b.writeGltf(dir.path(), "uvsets"), &warnings);
    for (const char* texture : {"metallicRoughnessTexture", "occlusionTexture"})
        EXPECT_EQ(countMentioning(warnings, std::string("meshes[0].primitives[0]: has no TEXCOORD_1, which the ") + texture +
                                                " of materials[0] 'stone' samples; it is sampled at uv (0,0)"),
                  1)
            << texture;
    EXPECT_EQ(countMentioning(warnings, "emissiveTexture"), 0) << "TEXCOORD_0 is there";
}
