// loadGltf on tangent frames: TANGENT as written (w stored exactly +-1, xyz made unit, a
// zero one repaired with a warning), tangents generated for a normal-mapped material from
// the normal texture's UV set and transform, none when that set is missing (a warning), and
// morph target TANGENT offsets posed with the mesh. Refusals of bad values are rows of
// test_gltf_bad_input.cpp; the generation itself is test_tangent_generation.cpp.
#include "engine/gltf/GltfLoader.h"
#include "engine/scene/Deform.h"

#include "gltf_test_support.h"
#include "../support/TangentExpectations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

using engine::test::expectTangent;

namespace {

using namespace gltf_test;

json& firstPrimitive(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }

int countMentioning(const std::vector<std::string>& warnings, const std::string& text) {
    return static_cast<int>(std::count_if(warnings.begin(), warnings.end(),
                                          [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

// The quad (z = 0, facing +z, NORMAL given) with TEXCOORD_0 showing an image upright: u
// along +x, v along -y (glTF's v grows down the image). No material.
GltfBuilder uprightQuad() {
    GltfBuilder b = quadScene();
    firstPrimitive(b)["attributes"]["NORMAL"] = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, 3, "VEC3");
    firstPrimitive(b)["attributes"]["TEXCOORD_0"] = b.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, 2, "VEC2");
    return b;
}

// Material 'bumpy' on the quad, whose normalTexture is `textureInfo` (index 0 added), of a
// tiny PNG in the buffer.
void addNormalMap(GltfBuilder& b, json textureInfo) {
    const std::vector<std::uint8_t>& png = tinyPng();
    b.doc["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    textureInfo["index"] = 0;
    b.doc["materials"] = {{{"name", "bumpy"}, {"normalTexture", textureInfo}}};
    firstPrimitive(b)["material"] = 0;
}

const std::vector<glm::vec4>& loadedTangents(const engine::Scene& scene) {
    return scene.meshes.at(0).primitives.at(0).tangents;
}

} // namespace

TEST(GltfTangents, FloatTangentsAreMadeUnitAndTheirSignsExact) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    // Lengths 2, 3 and sqrt 2; signs a float exporter rounded (within the 1e-3 allowed).
    firstPrimitive(b)["attributes"]["TANGENT"] =
        b.addFloats({2, 0, 0, 0.9995f, 0, 3, 0, -1.0004f, 1, 1, 0, 1, 0, -1, 0, -1}, 4, "VEC4");
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "tangents"));
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    expectTangent(tangents[0], {1, 0, 0}, 1.0f);
    expectTangent(tangents[1], {0, 1, 0}, -1.0f);
    expectTangent(tangents[2], {0.70710678f, 0.70710678f, 0}, 1.0f);
    expectTangent(tangents[3], {0, -1, 0}, -1.0f);
}

// KHR_mesh_quantization's normalized BYTE: 127 is 1, and -128 and -127 are both -1.
TEST(GltfTangents, NormalizedByteTangentsDecodeToExactSigns) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    const std::vector<std::int8_t> bytes = {127, 0, 0, 127, 0, 127, 0, -128, 0, 0, -127, -127, 64, 64, 0, 127};
    firstPrimitive(b)["attributes"]["TANGENT"] =
        b.addAccessor(b.addView(bytes.data(), bytes.size()), kByte, 4, "VEC4", /*normalized=*/true);
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "snorm"));
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    expectTangent(tangents[0], {1, 0, 0}, 1.0f);
    expectTangent(tangents[1], {0, 1, 0}, -1.0f);
    expectTangent(tangents[2], {0, 0, -1}, -1.0f);
    expectTangent(tangents[3], {0.70710678f, 0.70710678f, 0}, 1.0f);
}

TEST(GltfTangents, ZeroLengthTangentsArePerpendicularToTheNormalWithOneWarning) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    firstPrimitive(b)["attributes"]["TANGENT"] =
        b.addFloats({1, 0, 0, 1, 0, 0, 0, -1, 0, 1, 0, 1, 0, 0, 0, 1}, 4, "VEC4");
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "zero"), &warnings);
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    for (const std::size_t v : {1u, 3u}) {
        const glm::vec3 xyz(tangents[v]);
        EXPECT_NEAR(glm::length(xyz), 1.0f, 1e-6f) << "vertex " << v;
        EXPECT_NEAR(glm::dot(xyz, glm::vec3(0, 0, 1)), 0.0f, 1e-6f) << "vertex " << v;
    }
    EXPECT_EQ(tangents[1].w, -1.0f) << "the file's sign is kept";
    EXPECT_EQ(tangents[3].w, 1.0f);
    expectTangent(tangents[2], {0, 1, 0}, 1.0f);  // the others as written
    EXPECT_EQ(countMentioning(warnings, "TANGENT of 2 vertices (the first: vertex 1) has zero length"), 1);
    EXPECT_EQ(countMentioning(warnings, "zero length"), 1) << "one warning per primitive";
}

// The glTF convention (Tangents.h): tangent along increasing u; bitangent, the map's +Y, up
// the image, which is decreasing v. Upright on a quad facing +z: +x, bitangent +y =
// cross(+z, +x), so w = +1.
TEST(GltfTangents, AreGeneratedForANormalMappedMaterialWithoutTangent) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    addNormalMap(b, json::object());
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "generated"), &warnings);
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    for (const glm::vec4& tangent : tangents) expectTangent(tangent, {1, 0, 0}, 1.0f);
    EXPECT_EQ(countMentioning(warnings, "tangent"), 0);
}

TEST(GltfTangents, AreNotGeneratedWithoutANormalTexture) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    b.doc["materials"] = {{{"name", "flat"}}};
    firstPrimitive(b)["material"] = 0;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "flat"));
    EXPECT_TRUE(loadedTangents(scene).empty());
}

// TEXCOORD_1 mirrors the image left to right (u along -x, v still along -y): the tangent
// follows u to -x and the frame's handedness flips, w = -1 (cross(+z, -x) = -y, not up).
TEST(GltfTangents, AreGeneratedFromTheNormalTexturesUvSet) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    firstPrimitive(b)["attributes"]["TEXCOORD_1"] = b.addFloats({1, 1, 0, 1, 0, 0, 1, 0}, 2, "VEC2");
    addNormalMap(b, {{"texCoord", 1}});
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "uv1"));
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    for (const glm::vec4& tangent : tangents) expectTangent(tangent, {-1, 0, 0}, -1.0f);
}

// KHR_texture_transform rotation pi/2 (UvTransform: u' = v, v' = -u): u' grows along -y and
// v' along -x, so the tangent is -y and the bitangent (decreasing v') +x = cross(+z, -y):
// w = +1.
TEST(GltfTangents, FollowTheNormalTexturesTransform) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    addNormalMap(b, {{"extensions", {{"KHR_texture_transform", {{"rotation", 1.5707963267948966}}}}}});
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "rotated"));
    const std::vector<glm::vec4>& tangents = loadedTangents(scene);
    ASSERT_EQ(tangents.size(), 4u);
    for (const glm::vec4& tangent : tangents) expectTangent(tangent, {0, -1, 0}, 1.0f);
}

TEST(GltfTangents, MissingUvSetOfTheNormalTextureGivesNoTangentsAndOneWarning) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    addNormalMap(b, {{"texCoord", 1}});
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "noset"), &warnings);
    EXPECT_TRUE(loadedTangents(scene).empty());
    EXPECT_EQ(countMentioning(warnings, "meshes[0].primitives[0]: has no TEXCOORD_1, which the normalTexture of "
                                        "materials[0] 'bumpy' samples; no tangents are generated and the normal "
                                        "map is ignored for this primitive"),
              1);
    EXPECT_EQ(countMentioning(warnings, "TEXCOORD_1"), 1);
}

// A target turning the tangents from +x toward +y, at weight 1: posed (0, 1, 0), the sign
// as loaded.
TEST(GltfTangents, MorphTargetTangentOffsetsAreReadAndPosed) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    firstPrimitive(b)["attributes"]["TANGENT"] =
        b.addFloats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1, 1, 0, 0, -1}, 4, "VEC4");
    const std::vector<float> offsets = {-1, 1, 0, -1, 1, 0, -1, 1, 0, -1, 2, 0};
    firstPrimitive(b)["targets"] = json::array({{{"TANGENT", b.addFloats(offsets, 3, "VEC3")}}});
    b.doc["meshes"][0]["weights"] = {1.0};
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "morphed"));
    const engine::Primitive& primitive = scene.meshes.at(0).primitives.at(0);
    ASSERT_EQ(primitive.targets.size(), 1u);
    ASSERT_EQ(primitive.targets[0].tangents.size(), 4u);
    EXPECT_EQ(primitive.targets[0].tangents[3], glm::vec3(-1, 2, 0));

    ASSERT_EQ(scene.meshInstances.size(), 1u);
    ASSERT_TRUE(scene.meshInstances[0].deformed);
    const std::vector<glm::vec4>& posed = scene.meshInstances[0].deformed->primitives.at(0).tangents;
    ASSERT_EQ(posed.size(), 4u);
    expectTangent(posed[0], {0, 1, 0}, 1.0f);
    expectTangent(posed[2], {0, 1, 0}, -1.0f);
    expectTangent(posed[3], {0, 1, 0}, -1.0f);  // (1, 0, 0) + (-1, 2, 0), normalized
}

TEST(GltfTangents, MorphTangentOffsetsWithoutTangentAreDroppedWithAWarning) {
    TempDir dir;
    GltfBuilder b = uprightQuad();
    addNormalMap(b, json::object());  // generated tangents: not what the offsets were made for
    const std::vector<float> offsets = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    firstPrimitive(b)["targets"] = json::array({{{"TANGENT", b.addFloats(offsets, 3, "VEC3")}}});
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "offsets"), &warnings);
    const engine::Primitive& primitive = scene.meshes.at(0).primitives.at(0);
    ASSERT_EQ(primitive.targets.size(), 1u);
    EXPECT_TRUE(primitive.targets[0].tangents.empty());
    EXPECT_EQ(primitive.tangents.size(), 4u) << "generated all the same";
    EXPECT_EQ(countMentioning(warnings, "morph target TANGENT offsets ignored: the primitive has no TANGENT"), 1);
}
