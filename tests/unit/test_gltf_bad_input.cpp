// loadGltf on bad input: every case is one valid file broken in one place, and must throw
// an InputError naming the file, the object and the reason (notes/tinygltf-2.7.0.md lists
// the hazards several of these cases would trigger inside tinygltf 2.7.0).
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include "gltf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace gltf_test;

json& firstPrimitive(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }

void setU32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
    std::memcpy(bytes.data() + offset, &value, 4);
}

// --- Containers and JSON ---------------------------------------------------------------

TEST(GltfBadInput, MissingFile) {
    TempDir dir;
    expectLoadError(dir / "absent.gltf", {"absent.gltf", "no such file"});
}

TEST(GltfBadInput, SceneFileIsADirectory) {
    TempDir dir;
    fs::create_directories(dir / "folder.gltf");
    expectLoadError(dir / "folder.gltf", {"folder.gltf", "is not a regular file"});
}

TEST(GltfBadInput, MalformedJson) {
    TempDir dir;
    writeText(dir / "bad.gltf", R"({"asset": {"version": "2.0"},, "nodes": []})");
    expectLoadError(dir / "bad.gltf", {"bad.gltf", "JSON", "parse error at line 1"});
}

TEST(GltfBadInput, NaNInNodeMatrixIsNotJson) {
    // JSON has no NaN and nlohmann refuses numbers beyond double, so a non-finite matrix
    // cannot get past the parser; the loader's own finiteness check is a second guard.
    TempDir dir;
    std::string text = quadScene().doc.dump();
    text.replace(text.find("\"name\":\"Quad\""), 13, R"("name":"Quad","matrix":[NaN,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1])");
    writeText(dir / "nan.gltf", text);
    expectLoadError(dir / "nan.gltf", {"nan.gltf", "JSON", "syntax error", "invalid literal"});

    text.replace(text.find("NaN"), 3, "1e400");
    writeText(dir / "huge.gltf", text);
    expectLoadError(dir / "huge.gltf", {"huge.gltf", "JSON", "number overflow", "1e400"});
}

TEST(GltfBadInput, DeepJsonNestingIsRefusedBeforeParsing) {
    // ~20 000 levels overflow tinygltf 2.7.0's recursive walk of extras.
    TempDir dir;
    std::string text = quadScene().doc.dump();
    const std::string deep = std::string(20000, '[') + std::string(20000, ']');
    text.insert(text.rfind('}'), ",\"extras\":" + deep);
    writeText(dir / "deep.gltf", text);
    expectLoadError(dir / "deep.gltf", {"deep.gltf", "JSON", "nesting deeper than 64 levels"});
}

TEST(GltfBadInput, DeepJsonNestingInsideGlb) {
    TempDir dir;
    GltfBuilder b = quadScene();
    json deep = json::array();
    for (int i = 0; i < 100; ++i) deep = json::array({deep});
    b.doc["extras"] = deep;
    expectLoadError(b.writeGlb(dir.path(), "deep"), {"deep.glb", "JSON", "nesting deeper than 64 levels"});
}

TEST(GltfBadInput, UnsupportedAssetVersion) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["asset"]["version"] = "1.0";
    expectLoadError(b.writeGltf(dir.path(), "old"), {"old.gltf", "asset", "version '1.0' is not supported"});
}

TEST(GltfBadInput, UnsupportedRequiredExtension) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["extensionsRequired"] = {"KHR_lights_punctual", "KHR_draco_mesh_compression"};
    expectLoadError(b.writeGltf(dir.path(), "draco"),
                    {"draco.gltf", "extensionsRequired", "'KHR_draco_mesh_compression' is not supported"});
}

TEST(GltfBadInput, TinygltfErrorsArePassedOn) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["type"] = "VEC5";
    expectLoadError(b.writeGltf(dir.path(), "vec5"), {"vec5.gltf", "tinygltf", "VEC5"});
}

TEST(GltfBadInput, TruncatedGlb) {
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    glb.resize(glb.size() - 10);
    writeBytes(dir / "cut.glb", glb);
    expectLoadError(dir / "cut.glb", {"cut.glb", "GLB header", "truncated", "the file has"});

    glb.resize(7);
    writeBytes(dir / "stub.glb", glb);
    expectLoadError(dir / "stub.glb", {"stub.glb", "GLB header", "truncated"});
}

TEST(GltfBadInput, GlbJsonChunkLengthLies) {
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    setU32(glb, 12, 0x7FFFFFF0);
    writeBytes(dir / "liar.glb", glb);
    expectLoadError(dir / "liar.glb", {"liar.glb", "GLB chunk 0 (JSON)", "runs past the end of the file"});
}

TEST(GltfBadInput, GlbBinChunkLengthLiesByLessThanItsHeader) {
    // tinygltf 2.7.0 forgets the BIN chunk's 8-byte header in its own check: a length 4
    // bytes too long would have it read past the end of the file.
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    std::uint32_t jsonLength;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    const std::size_t binHeader = 20 + jsonLength;
    std::uint32_t binLength;
    std::memcpy(&binLength, glb.data() + binHeader, 4);
    setU32(glb, binHeader, binLength + 4);
    writeBytes(dir / "binliar.glb", glb);
    expectLoadError(dir / "binliar.glb", {"binliar.glb", "GLB chunk 1 (BIN)", "runs past the end of the file"});
}

TEST(GltfBadInput, GlbVersionOtherThan2) {
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    setU32(glb, 4, 1);
    writeBytes(dir / "v1.glb", glb);
    expectLoadError(dir / "v1.glb", {"v1.glb", "GLB header", "version 1 is not supported"});
}

TEST(GltfBadInput, GlbLengthDisagreesWithFileSize) {
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    glb.insert(glb.end(), 16, 0);
    writeBytes(dir / "long.glb", glb);
    expectLoadError(dir / "long.glb", {"long.glb", "GLB header", "but the file has"});
}

TEST(GltfBadInput, GlbBufferWithByteLengthZeroDoesNotAbort) {
    // tinygltf 2.7.0 throws std::out_of_range here.
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", 0}}};
    expectLoadError(b.writeGlb(dir.path(), "empty"), {"empty.glb", "buffers[0]", "byteLength is 0"});
}

TEST(GltfBadInput, GlbBufferLongerThanTheBinChunk) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size() + 100}}};
    expectLoadError(b.writeGlb(dir.path(), "short"), {"short.glb", "buffers[0]", "more than the GLB BIN chunk holds"});
}

// --- URIs and files ----------------------------------------------------------------------

// The quad scene with its buffer's uri replaced (the .bin is still written next to it).
fs::path quadWithBufferUri(const TempDir& dir, const std::string& uri, const std::string& name) {
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", uri}}};
    return b.writeGltf(dir.path(), name);
}

// A copy of the quad's buffer outside `dir`, so refusals cannot be blamed on a missing file.
struct OutsideFile {
    TempDir elsewhere;
    fs::path path = elsewhere / "secret.bin";
    OutsideFile() { writeBytes(path, quadScene().bin); }
};

TEST(GltfBadInput, MissingBufferFile) {
    TempDir dir;
    expectLoadError(quadWithBufferUri(dir, "missing.bin", "nobin"),
                    {"nobin.gltf", "buffers[0]", "uri 'missing.bin'", "no such file"});
}

TEST(GltfBadInput, DotDotUriIsRefused) {
    TempDir dir;
    fs::create_directories(dir / "scene");
    writeBytes(dir / "outside.bin", quadScene().bin);
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "../outside.bin"}}};
    expectLoadError(b.writeGltf(dir / "scene", "up"), {"up.gltf", "buffers[0]", "climbs out of the scene's folder"});
}

TEST(GltfBadInput, PercentEncodedDotDotUriIsRefused) {
    TempDir dir;
    fs::create_directories(dir / "scene");
    writeBytes(dir / "outside.bin", quadScene().bin);
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "%2e%2e/outside.bin"}}};
    expectLoadError(b.writeGltf(dir / "scene", "encoded"),
                    {"encoded.gltf", "buffers[0]", "'%2e%2e/outside.bin' climbs out"});
}

TEST(GltfBadInput, AbsoluteUriIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    expectLoadError(quadWithBufferUri(dir, outside.path.string(), "absolute"),
                    {"absolute.gltf", "buffers[0]", "is an absolute path"});
}

TEST(GltfBadInput, FileSchemeUriIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    expectLoadError(quadWithBufferUri(dir, "file://" + outside.path.string(), "scheme"),
                    {"scheme.gltf", "buffers[0]", "has a scheme"});
}

TEST(GltfBadInput, SymlinkLeadingOutIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    fs::create_symlink(outside.path, dir / "link.bin");
    expectLoadError(quadWithBufferUri(dir, "link.bin", "symlink"),
                    {"symlink.gltf", "buffers[0]", "uri 'link.bin'", "outside the scene's folder"});
}

TEST(GltfBadInput, DirectoryAsUriIsRefused) {
    // tinygltf 2.7.0 would try to allocate 0x7fff... bytes and abort.
    TempDir dir;
    fs::create_directories(dir / "data.bin");
    expectLoadError(quadWithBufferUri(dir, "data.bin", "dir"), {"dir.gltf", "buffers[0]", "is not a regular file"});
}

TEST(GltfBadInput, ImageUriLeadingOutIsRefused) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["images"] = {{{"uri", "/etc/passwd"}}};
    expectLoadError(b.writeGltf(dir.path(), "image"), {"image.gltf", "images[0]", "is an absolute path"});
}

TEST(GltfBadInput, DataUriShorterThanByteLength) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size() + 3}, {"uri", "data:application/octet-stream;base64," + base64(b.bin)}}};
    expectLoadError(b.writeGltf(dir.path(), "datauri"),
                    {"datauri.gltf", "buffers[0]", "data URI holds 60 bytes, byteLength says 63"});
}

TEST(GltfBadInput, BufferFileLargerThanTheLimit) {
    TempDir dir;
    engine::GltfLoadOptions options;
    options.maxFileBytes = 1000;
    GltfBuilder b = quadScene();
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "big.bin"}}};
    b.bin.resize(2000);  // the file, not the declared length, is over the limit
    expectLoadError(b.writeGltf(dir.path(), "big"),
                    {"big.gltf", "buffers[0]", "uri 'big.bin' is 2000 bytes, more than the limit of 1000"}, options);
}

// --- Binary layout ------------------------------------------------------------------------

TEST(GltfBadInput, AccessorRunsPastItsView) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["count"] = 5;
    expectLoadError(b.writeGltf(dir.path(), "past"),
                    {"past.gltf", "accessors[0]", "runs past the end of bufferViews[0] (needs 60 bytes, has 48)"});
}

TEST(GltfBadInput, AccessorOffsetRunsPastItsView) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["byteOffset"] = 4;
    expectLoadError(b.writeGltf(dir.path(), "offset"),
                    {"offset.gltf", "accessors[0]", "runs past the end of bufferViews[0] (needs 52 bytes, has 48)"});
}

TEST(GltfBadInput, BufferViewRunsPastItsBuffer) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["bufferViews"][1]["byteLength"] = 1000;
    expectLoadError(b.writeGltf(dir.path(), "view"),
                    {"view.gltf", "bufferViews[1]", "runs past the end of buffers[0] (needs 1048 bytes, has 60)"});
}

TEST(GltfBadInput, ByteStrideNotAMultipleOf4) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["bufferViews"][0]["byteStride"] = 14;
    expectLoadError(b.writeGltf(dir.path(), "stride"), {"stride.gltf", "bufferViews[0]", "byteStride 14"});
}

TEST(GltfBadInput, ByteStrideAbove252) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["bufferViews"][0]["byteStride"] = 256;
    expectLoadError(b.writeGltf(dir.path(), "stride"), {"stride.gltf", "bufferViews[0]", "byteStride 256"});
}

TEST(GltfBadInput, ByteStrideSmallerThanTheElement) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["bufferViews"][0]["byteStride"] = 8;
    expectLoadError(b.writeGltf(dir.path(), "stride"),
                    {"stride.gltf", "accessors[0]", "byteStride 8 is smaller than the element size 12"});
}

TEST(GltfBadInput, HugeCountIsRefusedBeforeAllocating) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["count"] = 2000000000;
    const fs::path file = b.writeGltf(dir.path(), "huge");
    expectLoadError(file, {"huge.gltf", "accessors[0]", "count 2000000000 is more than the limit of 134217728"});
    // Even with the limit lifted, the range check comes before any allocation.
    engine::GltfLoadOptions unlimited;
    unlimited.maxElementCount = std::numeric_limits<std::uint64_t>::max();
    expectLoadError(file, {"huge.gltf", "accessors[0]", "runs past the end of bufferViews[0] (needs 24000000000 bytes"},
                    unlimited);
}

TEST(GltfBadInput, CountAndStrideOverflowing64Bits) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["count"] = std::numeric_limits<std::uint64_t>::max() / 4;
    engine::GltfLoadOptions unlimited;
    unlimited.maxElementCount = std::numeric_limits<std::uint64_t>::max();
    expectLoadError(b.writeGltf(dir.path(), "overflow"), {"overflow.gltf", "accessors[0]", "overflow 64 bits"}, unlimited);
}

TEST(GltfBadInput, CountZero) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["count"] = 0;
    expectLoadError(b.writeGltf(dir.path(), "zero"), {"zero.gltf", "accessors[0]", "count is 0"});
}

TEST(GltfBadInput, SparseAccessorsAreRefused) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 1}, {"componentType", kUnsignedShort}}},
                                       {"values", {{"bufferView", 0}}}};
    expectLoadError(b.writeGltf(dir.path(), "sparse"), {"sparse.gltf", "accessors[0]", "sparse accessors are not supported"});
}

TEST(GltfBadInput, AttributeOfTheWrongType) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["accessors"][0]["type"] = "VEC2";
    b.doc["accessors"][0]["count"] = 6;
    expectLoadError(b.writeGltf(dir.path(), "type"),
                    {"type.gltf", "accessors[0]", "used as POSITION of meshes[0].primitives[0], must be VEC3"});
}

// --- Values ----------------------------------------------------------------------------

TEST(GltfBadInput, IndexPastTheVertexCount) {
    TempDir dir;
    GltfBuilder b = quadScene();
    firstPrimitive(b)["indices"] = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 7});
    expectLoadError(b.writeGltf(dir.path(), "index"),
                    {"index.gltf", "accessors[2]", "index 7 (element 5) is past the vertex count 4"});
}

TEST(GltfBadInput, NaNPosition) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    firstPrimitive(b)["attributes"]["POSITION"] = b.addFloats({0, 0, 0, 1, 0, 0, 1, nan, 0, 0, 1, 0}, 3, "VEC3");
    expectLoadError(b.writeGltf(dir.path(), "nan"),
                    {"nan.gltf", "accessors[2]", "POSITION", "element 2", "not a finite number"});
}

TEST(GltfBadInput, InfiniteNormal) {
    TempDir dir;
    GltfBuilder b = quadScene();
    const float inf = std::numeric_limits<float>::infinity();
    firstPrimitive(b)["attributes"]["NORMAL"] = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, inf, 0, 0, 1}, 3, "VEC3");
    expectLoadError(b.writeGltf(dir.path(), "inf"), {"inf.gltf", "accessors[2]", "NORMAL", "not a finite number"});
}

TEST(GltfBadInput, TriangleListNotAMultipleOf3) {
    TempDir dir;
    GltfBuilder b = quadScene();
    firstPrimitive(b)["indices"] = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0});
    expectLoadError(b.writeGltf(dir.path(), "partial"),
                    {"partial.gltf", "meshes[0].primitives[0]", "not a multiple of 3"});
}

TEST(GltfBadInput, NodeMatrixOfWrongLength) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0};
    expectLoadError(b.writeGltf(dir.path(), "matrix"), {"matrix.gltf", "nodes[0] 'Quad'", "matrix has 15 numbers, not 16"});
}

TEST(GltfBadInput, ZeroQuaternion) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectLoadError(b.writeGltf(dir.path(), "quat"), {"quat.gltf", "nodes[0] 'Quad'", "rotation is a zero quaternion"});
}

// --- Graph and references ------------------------------------------------------------------

TEST(GltfBadInput, NodeCycle) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.addNode({{"name", "A"}, {"children", {2}}});
    b.addNode({{"name", "B"}, {"children", {1}}});
    expectLoadError(b.writeGltf(dir.path(), "cycle"), {"cycle.gltf", "nodes[", "is its own ancestor"});
}

TEST(GltfBadInput, NodeThatIsItsOwnChild) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["children"] = {0};
    expectLoadError(b.writeGltf(dir.path(), "self"), {"self.gltf", "nodes[0] 'Quad'", "lists itself as a child"});
}

TEST(GltfBadInput, NodeWithTwoParents) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.addNode({{"name", "P1"}, {"children", {0}}});
    b.addNode({{"name", "P2"}, {"children", {0}}});
    b.setScene({1, 2});
    expectLoadError(b.writeGltf(dir.path(), "parents"),
                    {"parents.gltf", "nodes[0] 'Quad'", "has two parents: nodes[1] 'P1' and nodes[2] 'P2'"});
}

TEST(GltfBadInput, SceneRootThatIsAChild) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.addNode({{"name", "Parent"}, {"children", {0}}});
    b.setScene({0, 1});
    expectLoadError(b.writeGltf(dir.path(), "root"), {"root.gltf", "scenes[0]", "is a child of nodes[1] 'Parent'"});
}

TEST(GltfBadInput, SceneRootIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.setScene({0, 9});
    expectLoadError(b.writeGltf(dir.path(), "roots"), {"roots.gltf", "scenes[0]", "node 9 does not exist"});
}

TEST(GltfBadInput, ChildIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["children"] = {5};
    expectLoadError(b.writeGltf(dir.path(), "child"), {"child.gltf", "nodes[0] 'Quad'", "child node 5 does not exist"});
}

// --- Property types (tinygltf 2.7.0 would silently skip these) ----------------------------

TEST(GltfBadInput, PrimitivesThatAreNotAnArray) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["meshes"][0]["primitives"] = {{"not an array", b.doc["meshes"][0]["primitives"][0]}};
    expectLoadError(b.writeGltf(dir.path(), "types"), {"types.gltf", "meshes[0].primitives", "is not an array"});
}

TEST(GltfBadInput, NegativeIndex) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["children"] = {-1};
    expectLoadError(b.writeGltf(dir.path(), "types"),
                    {"types.gltf", "nodes[0].children", "is not an array of non-negative integers"});
}

TEST(GltfBadInput, AttributeIndexThatIsAString) {
    TempDir dir;
    GltfBuilder b = quadScene();
    firstPrimitive(b)["attributes"]["POSITION"] = "0";
    expectLoadError(b.writeGltf(dir.path(), "types"),
                    {"types.gltf", "meshes[0].primitives[0].attributes.POSITION", "is not a non-negative integer"});
}

TEST(GltfBadInput, MeshIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["mesh"] = 3;
    expectLoadError(b.writeGltf(dir.path(), "mesh"), {"mesh.gltf", "nodes[0] 'Quad'", "mesh 3 does not exist"});
}

TEST(GltfBadInput, MaterialIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    firstPrimitive(b)["material"] = 0;
    expectLoadError(b.writeGltf(dir.path(), "material"),
                    {"material.gltf", "meshes[0].primitives[0]", "material 0 does not exist"});
}

TEST(GltfBadInput, CameraIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["camera"] = 0;
    expectLoadError(b.writeGltf(dir.path(), "camera"), {"camera.gltf", "nodes[0] 'Quad'", "camera 0 does not exist"});
}

TEST(GltfBadInput, CameraWithBadValues) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["cameras"] = {{{"name", "eye"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 1.0}, {"zfar", 0.5}}}}};
    expectLoadError(b.writeGltf(dir.path(), "camera"), {"camera.gltf", "cameras[0] 'eye'", "perspective.zfar 0.5 must be a finite number > znear"});
}

// --- Lights and extras -------------------------------------------------------------------

// The quad scene with one KHR_lights_punctual light (as given) placed by a node.
fs::path sceneWithLight(const TempDir& dir, const json& light, const std::string& name) {
    GltfBuilder b = quadScene();
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {light};
    b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.setScene({0, 1});
    return b.writeGltf(dir.path(), name);
}

TEST(GltfBadInput, LightOfUnknownType) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"name", "sun"}, {"type", "area"}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0] 'sun'", "type 'area' is not directional, point or spot"});
}

TEST(GltfBadInput, LightWithNegativeIntensity) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "point"}, {"intensity", -1}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "intensity -1 is not a finite number >= 0"});
}

TEST(GltfBadInput, LightWithNegativeColor) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "point"}, {"color", {1, -0.5, 1}}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "color[1] -0.5 is not a finite number >= 0"});
}

TEST(GltfBadInput, LightColorOfTwoNumbers) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "point"}, {"color", {1, 1}}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "color is not an array of 3 numbers"});
}

TEST(GltfBadInput, LightWithZeroRange) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "spot"}, {"range", 0}, {"spot", json::object()}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "range 0 is not a finite number > 0"});
}

TEST(GltfBadInput, SpotInnerAngleNotBelowOuter) {
    TempDir dir;
    expectLoadError(
        sceneWithLight(dir, {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}}, "light"),
        {"light.gltf", "KHR_lights_punctual.lights[0]", "spot.innerConeAngle 0.5 is not below outerConeAngle 0.5"});
}

TEST(GltfBadInput, SpotOuterAngleAboveHalfPi) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "spot.outerConeAngle 2 is more than pi/2"});
}

TEST(GltfBadInput, SpotLightWithoutSpot) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "spot"}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "spot is missing"});
}

TEST(GltfBadInput, LightExtrasNotAnObject) {
    TempDir dir;
    expectLoadError(sceneWithLight(dir, {{"type", "point"}, {"extras", 5}}, "light"),
                    {"light.gltf", "KHR_lights_punctual.lights[0]", "extras is not an object"});
}

TEST(GltfBadInput, NodeLightIndexOutOfRange) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 4}}}};
    expectLoadError(b.writeGltf(dir.path(), "light"),
                    {"light.gltf", "nodes[0] 'Quad'", "KHR_lights_punctual light 4 does not exist"});
}

TEST(GltfBadInput, NodeLightReferenceNotAnInteger) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", "sun"}}}};
    expectLoadError(b.writeGltf(dir.path(), "light"),
                    {"light.gltf", "nodes[0] 'Quad'", "KHR_lights_punctual.light is missing or not an integer"});
}

TEST(GltfBadInput, ShadowExtraThatIsNotABoolean) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["nodes"][0]["extras"] = {{"cast_shadows", "no"}};
    expectLoadError(b.writeGltf(dir.path(), "extras"),
                    {"extras.gltf", "nodes[0] 'Quad'", "extras.cast_shadows is not a boolean"});
}

TEST(GltfBadInput, UnknownAlphaMode) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["materials"] = {{{"name", "glass"}, {"alphaMode", "TRANSLUCENT"}}};
    expectLoadError(b.writeGltf(dir.path(), "alpha"),
                    {"alpha.gltf", "materials[0] 'glass'", "alphaMode 'TRANSLUCENT' is not OPAQUE, MASK or BLEND"});
}

// --- Images ----------------------------------------------------------------------------

// A 2x1 PNG (see test_gltf_loader.cpp); its IHDR width is at byte 16, its zlib data at 41.
const std::vector<std::uint8_t> kTinyPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4, 0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00,
    0x0e, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x42, 0x0d, 0x00, 0x0f, 0x7a, 0x03,
    0x7e, 0x77, 0xe9, 0x7f, 0x97, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

// The quad scene with one image stored in a bufferView of the GLB.
fs::path sceneWithImage(const TempDir& dir, const std::vector<std::uint8_t>& encoded, const std::string& name) {
    GltfBuilder b = quadScene();
    b.doc["images"] = {{{"name", "albedo"}, {"bufferView", b.addView(encoded.data(), encoded.size())},
                        {"mimeType", "image/png"}}};
    return b.writeGlb(dir.path(), name);
}

TEST(GltfBadInput, ImageWhosePixelsFailToDecode) {
    TempDir dir;
    std::vector<std::uint8_t> png = kTinyPng;
    png[41] = 0x00;  // zlib header byte: the header still reads, the pixels do not
    png[42] = 0x00;
    expectLoadError(sceneWithImage(dir, png, "broken"), {"broken.glb", "images[0] 'albedo'", "failed to decode"});
}

TEST(GltfBadInput, ImageWithUnreadableHeader) {
    TempDir dir;
    std::vector<std::uint8_t> png(kTinyPng.begin(), kTinyPng.begin() + 12);
    expectLoadError(sceneWithImage(dir, png, "header"), {"header.glb", "images[0] 'albedo'", "cannot read the image header"});
}

TEST(GltfBadInput, ImageThatIsNeitherPngNorJpeg) {
    TempDir dir;
    const std::string gif = "GIF89a\x01\x00\x01\x00\x00\x00\x00;";
    expectLoadError(sceneWithImage(dir, std::vector<std::uint8_t>(gif.begin(), gif.end()), "gif"),
                    {"gif.glb", "images[0] 'albedo'", "is not a PNG or JPEG file (mimeType image/png)"});
}

TEST(GltfBadInput, ImageLargerThanTheLimitIsRefusedBeforeDecoding) {
    TempDir dir;
    std::vector<std::uint8_t> png = kTinyPng;
    setU32(png, 16, 0xA0860100);  // big-endian 100000
    expectLoadError(sceneWithImage(dir, png, "bomb"), {"bomb.glb", "images[0] 'albedo'", "100000x1 pixels is outside 1..8192"});
}

TEST(GltfBadInput, ImageFileMissing) {
    TempDir dir;
    GltfBuilder b = quadScene();
    b.doc["images"] = {{{"uri", "albedo.png"}}};
    expectLoadError(b.writeGltf(dir.path(), "noimage"), {"noimage.gltf", "images[0]", "uri 'albedo.png'", "no such file"});
}

} // namespace
