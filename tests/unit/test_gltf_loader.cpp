// loadGltf on valid files: the three containers, transforms, mesh conversion, materials,
// images, cameras, lights and shadow extras; and every glTF 2.0 model Debian ships in
// assimp-testmodels. Bad input is in test_gltf_bad_input.cpp.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include "gltf_test_support.h"
#include "../support/AssimpTestModels.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <numbers>
#include <utility>
#include <vector>

namespace {

using namespace gltf_test;

const std::vector<std::uint8_t>& kTinyPng = tinyPng();  // gltf_test_support.h

// The quad of quadScene(), as loaded: checks geometry, generated normals and placement.
void expectLoadedQuad(const engine::Scene& scene) {
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
    const engine::Primitive& quad = scene.meshes[0].primitives[0];
    EXPECT_EQ(quad.positions.size(), 4u);
    EXPECT_EQ(quad.positions[2], glm::vec3(1, 1, 0));
    EXPECT_EQ(quad.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    ASSERT_EQ(quad.normals.size(), 4u);
    EXPECT_EQ(quad.normals[0], glm::vec3(0, 0, 1));
    EXPECT_TRUE(quad.texcoords.empty());
    EXPECT_EQ(quad.bounds.max, glm::dvec3(1, 1, 0));
    EXPECT_FALSE(scene.meshes[0].closed);
    ASSERT_EQ(scene.meshInstances.size(), 1u);
    EXPECT_EQ(scene.nodes[0].name, "Quad");
    EXPECT_EQ(scene.roots, std::vector<int>{0});
}

TEST(GltfLoader, LoadsGltfWithExternalBin) {
    TempDir dir;
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(quadScene().writeGltf(dir.path(), "quad"), &warnings);
    expectLoadedQuad(scene);
    EXPECT_NE(scene.sourcePath.find("quad.gltf"), std::string::npos);
    // The generated normals are reported.
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(),
                            [](const std::string& w) { return w.find("normals generated") != std::string::npos; }));
}

TEST(GltfLoader, LoadsGltfWithDataUriBuffer) {
    TempDir dir;
    const fs::path file = quadScene().writeGltf(dir.path(), "quad", BufferStorage::DataUri);
    fs::remove(dir / "quad.bin");  // proves the bytes came from the data URI
    expectLoadedQuad(engine::loadGltf(file));
}

TEST(GltfLoader, LoadsGlb) {
    TempDir dir;
    expectLoadedQuad(engine::loadGltf(quadScene().writeGlb(dir.path(), "quad")));
}

TEST(GltfLoader, ComposesTrsParentWithMatrixChild) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const double s = std::sqrt(0.5);
    // Parent: T(1,2,3) * R(90 degrees about y) * S(2). Child: matrix translating by (0,0,5).
    b.doc["nodes"][0] = {{"name", "Parent"},
                         {"translation", {1, 2, 3}},
                         {"rotation", {0, s, 0, s}},
                         {"scale", {2, 2, 2}},
                         {"children", {1}}};
    b.addNode({{"name", "Child"}, {"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}});
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "trs"));

    // Child origin: scaled to (0,0,10), rotated onto (10,0,0), translated to (11,2,3).
    const glm::dmat4& world = scene.nodes[1].world;
    EXPECT_NEAR(world[3][0], 11.0, 1e-12);
    EXPECT_NEAR(world[3][1], 2.0, 1e-12);
    EXPECT_NEAR(world[3][2], 3.0, 1e-12);
    // The child's +x axis: scaled by 2, rotated onto -z.
    EXPECT_NEAR(world[0][2], -2.0, 1e-12);
    EXPECT_EQ(scene.nodes[1].parent, 0);
    ASSERT_EQ(scene.meshInstances.size(), 1u);
    EXPECT_EQ(scene.meshInstances[0].node, 1);
    // The quad spans x in [0,1]: after the transform, world z runs from 3 down to 1.
    EXPECT_NEAR(scene.meshInstances[0].worldBounds.min.z, 1.0, 1e-12);
    EXPECT_NEAR(scene.meshInstances[0].worldBounds.max.z, 3.0, 1e-12);
}

TEST(GltfLoader, KeepsGivenNormalsAndReadsNormalizedTexcoords) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const int normals = b.addFloats({0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0}, 3, "VEC3");
    const std::vector<std::uint16_t> uv{0, 0, 65535, 0, 65535, 65535, 0, 32768};
    const int texcoords = b.addAccessor(b.addView(uv.data(), uv.size() * 2), kUnsignedShort, 4, "VEC2", true);
    b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = normals;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = texcoords;
    std::vector<std::string> warnings;
    const engine::Primitive p = engine::loadGltf(b.writeGltf(dir.path(), "uv"), &warnings).meshes[0].primitives[0];
    EXPECT_EQ(p.normals[3], glm::vec3(0, 1, 0));
    ASSERT_EQ(p.texcoords.size(), 4u);
    EXPECT_EQ(p.texcoords[2], glm::vec2(1, 1));
    EXPECT_NEAR(p.texcoords[3].y, 32768.0f / 65535.0f, 1e-7f);
    EXPECT_TRUE(warnings.empty());
}

TEST(GltfLoader, ReadsInterleavedAttributesThroughTheirStride) {
    TempDir dir;
    GltfBuilder b;
    // position (3 floats) + 1 float of padding per vertex: stride 16.
    const std::vector<float> interleaved{0, 0, 0, -9, 1, 0, 0, -9, 0, 1, 0, -9};
    const int view = b.addView(interleaved.data(), interleaved.size() * 4, 16);
    const int positions = b.addAccessor(view, kFloat, 3, "VEC3");
    b.addMesh({{"attributes", {{"POSITION", positions}}}});
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    const engine::Primitive p = engine::loadGltf(b.writeGltf(dir.path(), "stride")).meshes[0].primitives[0];
    EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));  // generated for a non-indexed primitive
}

// Loads one primitive of the given mode (indexed by u8 indices unless `indices` is empty).
engine::Primitive loadPrimitive(const TempDir& dir, int mode, const std::vector<float>& positions,
                                const std::vector<std::uint8_t>& indices) {
    GltfBuilder b;
    json primitive = {{"attributes", {{"POSITION", b.addFloats(positions, 3, "VEC3")}}}, {"mode", mode}};
    if (!indices.empty()) primitive["indices"] = b.addIndices(indices);
    b.addMesh(primitive);
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    return engine::loadGltf(b.writeGltf(dir.path(), "mode" + std::to_string(mode))).meshes[0].primitives[0];
}

// Every triangle's geometric normal points to +z: the conversion kept the winding.
void expectAllTrianglesFacePlusZ(const engine::Primitive& p) {
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
        const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]], c = p.positions[p.indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t / 3;
    }
}

TEST(GltfLoader, ConvertsTriangleStripKeepingItsWinding) {
    TempDir dir;
    const std::vector<float> zigzag{0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0, 2, 1, 0};
    // Top, bottom, top, bottom...: the first triangle (1,0,3) is counter-clockwise from +z,
    // and a strip keeps its first triangle's winding throughout.
    const engine::Primitive p = loadPrimitive(dir, 5, zigzag, {1, 0, 3, 2, 5, 4});
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{1, 0, 3, 0, 2, 3, 3, 2, 5, 2, 4, 5}));
    EXPECT_EQ(p.triangleCount(), 4u);
    expectAllTrianglesFacePlusZ(p);
}

TEST(GltfLoader, ConvertsTriangleFanKeepingItsWinding) {
    TempDir dir;
    // Center, then four rim vertices counter-clockwise: a fan of three triangles.
    const std::vector<float> fan{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0};
    const engine::Primitive p = loadPrimitive(dir, 6, fan, {});
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
    expectAllTrianglesFacePlusZ(p);
}

TEST(GltfLoader, ReadsU8U16AndU32Indices) {
    TempDir dir;
    const std::vector<std::uint32_t> expected{0, 1, 2, 0, 2, 3};
    const auto loadWith = [&](auto indices, const std::string& name) {
        GltfBuilder b = quadScene();
        b.doc["meshes"][0]["primitives"][0]["indices"] = b.addIndices(indices);
        return engine::loadGltf(b.writeGltf(dir.path(), name)).meshes[0].primitives[0].indices;
    };
    EXPECT_EQ(loadWith(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}, "u8"), expected);
    EXPECT_EQ(loadWith(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, "u16"), expected);
    EXPECT_EQ(loadWith(std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}, "u32"), expected);
}

TEST(GltfLoader, DropsPointsAndLinesWithAWarning) {
    TempDir dir;
    GltfBuilder b = quadScene();
    json points = b.doc["meshes"][0]["primitives"][0];
    points["mode"] = 0;
    json lines = points;
    lines["mode"] = 1;
    b.doc["meshes"][0]["primitives"].push_back(points);
    b.doc["meshes"][0]["primitives"].push_back(lines);
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "points"), &warnings);
    EXPECT_EQ(scene.meshes[0].primitives.size(), 1u);
    const auto mentions = [&](const std::string& text) {
        return std::any_of(warnings.begin(), warnings.end(),
                           [&](const std::string& w) { return w.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(mentions("meshes[0].primitives[1]: POINTS primitive dropped"));
    EXPECT_TRUE(mentions("meshes[0].primitives[2]: LINES primitive dropped"));
}

TEST(GltfLoader, ClosedMeshIsMarkedClosed) {
    TempDir dir;
    const CubeGeometry cube = splitVertexCube();
    GltfBuilder b;
    const int positions = b.addFloats(cube.positions, 3, "VEC3");
    b.addMesh({{"attributes", {{"POSITION", positions}}}, {"indices", b.addIndices(cube.indices)}});
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    const engine::Scene scene = engine::loadGltf(b.writeGlb(dir.path(), "cube"));
    EXPECT_TRUE(scene.meshes[0].closed);
    EXPECT_EQ(scene.meshes[0].bounds.min, glm::dvec3(-1));
    EXPECT_EQ(scene.worldBounds.max, glm::dvec3(1));
}

TEST(GltfLoader, ReadsPunctualLightsWithTheirValuesAndExtras) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensionsRequired"] = {"KHR_lights_punctual"};
    const json shadow = {{"variant", "woo"}, {"resolution", 2048}, {"polygon_offset", {1.0, 4.0}}};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"color", {1.0, 0.9, 0.8}}, {"intensity", 3.5},
         {"extras", {{"shadow", shadow}}}},
        {{"type", "point"}, {"range", 12.5}},
        {{"name", "lamp"}, {"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
    };
    b.addNode({{"name", "SunNode"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.addNode({{"name", "Bulb"}, {"translation", {0, 3, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    b.addNode({{"name", "SpotNode"}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    b.setScene({0, 1, 2, 3});
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "lights"));

    ASSERT_EQ(scene.lights.size(), 3u);
    const engine::Light& sun = scene.lights[0];
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(sun.type, engine::Light::Type::Directional);
    EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_EQ(sun.intensity, 3.5f);
    EXPECT_EQ(sun.range, 0.0);
    EXPECT_EQ(sun.extras["shadow"], shadow);
    EXPECT_EQ(scene.lights[1].type, engine::Light::Type::Point);
    EXPECT_EQ(scene.lights[1].range, 12.5);
    EXPECT_EQ(scene.lights[1].color, glm::vec3(1.0f));
    EXPECT_EQ(scene.lights[1].extras, json::object());
    EXPECT_EQ(scene.lights[2].type, engine::Light::Type::Spot);
    EXPECT_EQ(scene.lights[2].innerConeAngle, 0.2);
    EXPECT_EQ(scene.lights[2].outerConeAngle, 0.6);

    ASSERT_EQ(scene.lightInstances.size(), 3u);
    EXPECT_EQ(scene.nodes[2].light, 1);
    EXPECT_EQ(scene.findLightInstance("sun"), 0);
    EXPECT_EQ(scene.findLightInstance("Bulb"), 1);  // unnamed light: by its node's name
    EXPECT_EQ(scene.lightInstances[1].position(), glm::dvec3(0, 3, 0));
}

TEST(GltfLoader, ReadsPerspectiveAndOrthographicCameras) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["cameras"] = {
        {{"name", "persp"}, {"type", "perspective"},
         {"perspective", {{"yfov", 0.7}, {"znear", 0.05}, {"zfar", 250.0}, {"aspectRatio", 1.5}}}},
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 4.0}, {"ymag", 3.0}, {"znear", 0.0}, {"zfar", 50.0}}}},
    };
    b.addNode({{"name", "Eye"}, {"camera", 0}, {"translation", {0, 1, 10}}});
    b.addNode({{"name", "Top"}, {"camera", 1}});
    b.setScene({0, 1, 2});
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "cameras"));

    ASSERT_EQ(scene.cameras.size(), 2u);
    const engine::Camera& persp = scene.cameras[0];
    EXPECT_EQ(persp.type, engine::Camera::Type::Perspective);
    EXPECT_EQ(persp.yfov, 0.7);
    EXPECT_EQ(persp.znear, 0.05);
    EXPECT_EQ(persp.zfar, 250.0);
    EXPECT_EQ(persp.aspectRatio, 1.5);
    const engine::Camera& ortho = scene.cameras[1];
    EXPECT_EQ(ortho.type, engine::Camera::Type::Orthographic);
    EXPECT_EQ(ortho.xmag, 4.0);
    EXPECT_EQ(ortho.ymag, 3.0);
    EXPECT_EQ(ortho.zfar, 50.0);
    EXPECT_EQ(scene.findCameraInstance("persp"), 0);
    EXPECT_EQ(scene.findCameraInstance("Top"), 1);
    EXPECT_EQ(scene.cameraInstances[0].world[3][2], 10.0);
}

// The quad node with `quadExtras` and a second node "Floor" with `floorExtras`, loaded: each
// mesh instance's (cast, receive) flags.
std::vector<std::pair<bool, bool>> shadowFlagsOf(const json& quadExtras, const json& floorExtras) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["extras"] = quadExtras;
    b.addNode({{"name", "Floor"}, {"mesh", 0}, {"extras", floorExtras}});
    b.setScene({0, 1});
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "extras"));
    std::vector<std::pair<bool, bool>> flags;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        flags.emplace_back(instance.castShadows, instance.receiveShadows);
    return flags;
}

TEST(GltfLoader, ReadsCastAndReceiveShadowExtras) {
    EXPECT_EQ(shadowFlagsOf({{"cast_shadows", false}, {"label", "anything else is fine"}},
                            {{"receive_shadows", false}}),
              (std::vector<std::pair<bool, bool>>{{false, true}, {true, false}}));
}

// Blender writes a boolean custom property as the integer 0 or 1 (older files, and every
// property made as an integer): read as false and true. (Any other number is an error:
// test_gltf_bad_input.)
TEST(GltfLoader, ReadsBlendersZeroAndOneAsShadowFlags) {
    EXPECT_EQ(shadowFlagsOf({{"cast_shadows", 0}, {"receive_shadows", 1}}, {{"cast_shadows", 1}, {"receive_shadows", 0.0}}),
              (std::vector<std::pair<bool, bool>>{{false, true}, {true, false}}));
}

// Node extras are shared with other exporters: keys that are not ours load silently, but
// one that reads like ours (a typo, another spelling) is reported with the node and the key
// we read, since ignoring it silently would keep a shadow its author opted out of.
TEST(GltfLoader, WarnsAboutNodeExtrasThatLookLikeOurShadowFlags) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["extras"] = {{"cast_shadow", false}, {"receiveShadows", false}, {"label", "not ours"},
                                   {"shadow_color", "red"}};
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "typo"), &warnings);
    std::vector<std::string> aboutExtras;
    for (const std::string& warning : warnings)
        if (warning.find("extras.") != std::string::npos) aboutExtras.push_back(warning);
    const auto warned = [&](const std::string& text) {
        return std::any_of(aboutExtras.begin(), aboutExtras.end(),
                           [&](const std::string& warning) { return warning.find(text) != std::string::npos; });
    };
    EXPECT_EQ(aboutExtras.size(), 2u) << ::testing::PrintToString(aboutExtras);
    EXPECT_TRUE(warned("typo.gltf: nodes[0] 'Quad': extras.cast_shadow is not read (did you mean \"cast_shadows\"?)"))
        << ::testing::PrintToString(aboutExtras);
    EXPECT_TRUE(warned("typo.gltf: nodes[0] 'Quad': extras.receiveShadows is not read (did you mean \"receive_shadows\"?)"))
        << ::testing::PrintToString(aboutExtras);
    EXPECT_TRUE(scene.meshInstances[0].castShadows);  // a warning, not a reading
}

TEST(GltfLoader, ReadsMaterialsAndDecodesTheBaseColorImage) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["images"] = {{{"name", "checker"}, {"bufferView", b.addView(kTinyPng.data(), kTinyPng.size())},
                        {"mimeType", "image/png"}},
                       {{"uri", "tiny.png"}}};
    writeBytes(dir / "tiny.png", kTinyPng);
    b.doc["textures"] = {{{"source", 1}}};
    b.doc["materials"] = {{{"name", "paint"},
                           {"pbrMetallicRoughness",
                            {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}},
                             {"baseColorTexture", {{"index", 0}}},
                             {"metallicFactor", 0.0},
                             {"roughnessFactor", 0.3}}},
                           {"emissiveFactor", {0.1, 0.2, 0.3}},
                           {"doubleSided", true},
                           {"alphaMode", "MASK"},
                           {"alphaCutoff", 0.25}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const engine::Scene scene = engine::loadGltf(b.writeGlb(dir.path(), "material"));

    ASSERT_EQ(scene.materials.size(), 1u);
    const engine::Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "paint");
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_EQ(m.baseColorTexture.image, 1);
    EXPECT_EQ(m.metallicFactor, 0.0f);
    EXPECT_EQ(m.roughnessFactor, 0.3f);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(m.alphaMode, engine::AlphaMode::Mask);
    EXPECT_EQ(m.alphaCutoff, 0.25f);
    EXPECT_EQ(scene.meshes[0].primitives[0].material, 0);

    ASSERT_EQ(scene.images.size(), 2u);
    for (const engine::Image& image : scene.images) {
        EXPECT_EQ(image.width, 2);
        EXPECT_EQ(image.height, 1);
        EXPECT_EQ(image.rgba8, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 128}));
    }
    EXPECT_EQ(scene.images[0].name, "checker");
}

TEST(GltfLoader, DefaultMaterialValuesWhenTheFileOmitsThem) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["materials"] = {json::object()};
    const engine::Material m = engine::loadGltf(b.writeGltf(dir.path(), "defaults")).materials[0];
    EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(m.baseColorTexture.image, -1);
    EXPECT_EQ(m.emissiveFactor, glm::vec3(0.0f));
    EXPECT_EQ(m.alphaMode, engine::AlphaMode::Opaque);
    EXPECT_EQ(m.alphaCutoff, 0.5f);
}

TEST(GltfLoader, UriWithPercentEscapesInsideTheFolderIsRead) {
    TempDir dir;
    GltfBuilder b = quadScene();
    fs::create_directories(dir / "sub dir");
    writeBytes(dir / "sub dir" / "data.bin", b.bin);
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "sub%20dir/data.bin"}}};
    expectLoadedQuad(engine::loadGltf(b.writeGltf(dir.path(), "escaped")));
}

TEST(GltfLoader, FileWithoutScenesShowsEveryRootNode) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc.erase("scenes");
    b.doc.erase("scene");
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "noscene"), &warnings);
    EXPECT_EQ(scene.roots, std::vector<int>{0});
    EXPECT_EQ(scene.meshInstances.size(), 1u);
}

// Every glTF 2.0 model of Debian's assimp-testmodels either loads or is refused with an
// InputError: none may crash, hang or throw anything else. The outcome of each is printed
// for the record.
TEST(GltfLoader, AssimpTestModelsLoadOrThrowInputError) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    const fs::path root = engine::test::kAssimpGltf2Models;
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());

    int loaded = 0, refused = 0;
    for (const fs::path& file : files) {
        const std::string name = fs::relative(file, root).string();
        try {
            const engine::Scene scene = engine::loadGltf(file);
            ++loaded;
            std::cout << "[assimp] LOADED  " << name << " (" << scene.meshes.size() << " meshes, "
                      << scene.meshInstances.size() << " instances)\n";
        } catch (const engine::InputError& error) {
            ++refused;
            std::cout << "[assimp] REFUSED " << name << ": " << error.what() << "\n";
        } catch (const std::exception& error) {
            ADD_FAILURE() << name << " threw something other than InputError: " << error.what();
        }
    }
    std::cout << "[assimp] " << loaded << " loaded, " << refused << " refused, of " << files.size() << "\n";
}

} // namespace
