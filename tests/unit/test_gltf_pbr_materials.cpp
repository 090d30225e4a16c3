// loadGltf on the metallic-roughness material parts beyond the base color:
// KHR_materials_emissive_strength (a factor on the emissive color), and the material
// textures the lit pass does not sample yet, which must be reported rather than dropped
// silently. Refusals of bad values are rows of test_gltf_bad_input.cpp.
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

TEST(GltfPbrMaterials, TexturesNotSampledYetAreReportedPerMaterial) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["textures"] = {json::object()};
    const json texture = {{"index", 0}};
    b.doc["materials"] = {
        {{"name", "brick"},
         {"pbrMetallicRoughness", {{"metallicRoughnessTexture", texture}}},
         {"normalTexture", texture},
         {"occlusionTexture", texture},
         {"emissiveTexture", texture}},
        {{"name", "painted"}, {"pbrMetallicRoughness", {{"baseColorTexture", texture}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    std::vector<std::string> warnings;
    engine::loadGltf(b.writeGltf(dir.path(), "textures"), &warnings);
    for (const char* member : {"pbrMetallicRoughness.metallicRoughnessTexture", "normalTexture", "occlusionTexture",
                               "emissiveTexture"})
        EXPECT_EQ(countMentioning(warnings, std::string("materials[0] 'brick': ") + member + " is not read yet"), 1)
            << member;
    // The base color texture is read: 'painted' adds no such report.
    EXPECT_EQ(countMentioning(warnings, "is not read yet"), 4);
}
