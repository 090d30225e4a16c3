// loadGltf on bad input: every case is one valid file broken in one place, and must throw
// an InputError naming the file, the object and the reason (several of these
// cases would crash or read out of bounds inside tinygltf 2.7.0 without the loader's guards).
//
// Most cases are rows of two tables below: an edit of the quad scene (kQuadEdits) or of its
// GLB bytes (kGlbByteEdits), and the parts the message must contain: the file, the object,
// the reason. Cases that need files around the scene or other load options are TESTs.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include "gltf_test_support.h"
#include "../support/AssimpTestModels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <ostream>

namespace {

using namespace gltf_test;

json& firstPrimitive(GltfBuilder& b) { return b.doc["meshes"][0]["primitives"][0]; }

void setU32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t value) {
    std::memcpy(bytes.data() + offset, &value, 4);
}

// --- Table-driven cases ----------------------------------------------------------------------

// The parts a case's message must contain: the file ("name.gltf" or "name.glb", which also
// says how the case is written), the object, the reason (and any further parts).
using Message = std::vector<std::string>;

template <typename Edit>
struct BadInputCase {
    std::string name;  // the test's name
    Edit edit;
    Message message;
};
template <typename Edit>
void PrintTo(const BadInputCase<Edit>& c, std::ostream* out) { *out << c.name; }

struct CaseName {
    template <typename Param>
    std::string operator()(const ::testing::TestParamInfo<Param>& info) const { return info.param.name; }
};

using QuadEdit = std::function<void(GltfBuilder&)>;
using GlbByteEdit = std::function<void(std::vector<std::uint8_t>&)>;

// Edits that build the quad scene's rows: the value at a JSON pointer, a buffer uri, a light,
// an image.
QuadEdit set(const char* pointer, const json& value) {
    return [pointer = json::json_pointer(pointer), value](GltfBuilder& b) { b.doc[pointer] = value; };
}
QuadEdit bufferUri(const std::string& uri) {
    return [uri](GltfBuilder& b) { b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", uri}}}; };
}
// One KHR_lights_punctual light (as given) placed by a node.
QuadEdit withLight(const json& light) {
    return [light](GltfBuilder& b) {
        b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
        b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {light};
        b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        b.setScene({0, 1});
    };
}
// New vertex attribute (3 floats a vertex) or indices for the quad's primitive.
QuadEdit attribute(const char* name, const std::vector<float>& values) {
    return [name, values](GltfBuilder& b) { firstPrimitive(b)["attributes"][name] = b.addFloats(values, 3, "VEC3"); };
}
QuadEdit indices(const std::vector<std::uint16_t>& values) {
    return [values](GltfBuilder& b) { firstPrimitive(b)["indices"] = b.addIndices(values); };
}
// More nodes, and the scene's roots if given.
QuadEdit withNodes(const std::vector<json>& nodes, const std::vector<int>& roots = {}) {
    return [nodes, roots](GltfBuilder& b) {
        for (const json& node : nodes) b.addNode(node);
        if (!roots.empty()) b.setScene(roots);
    };
}
// Material 'leaf' on the quad, its baseColorTexture `textureInfo` (index 0 added) of texture 0
// (no image needed) with sampler 0 when `samplers` are given; `edit` may change the rest.
QuadEdit withTexture(json textureInfo, const json& samplers = nullptr) {
    return [textureInfo, samplers](GltfBuilder& b) mutable {
        textureInfo["index"] = 0;
        b.doc["textures"] = {json::object()};
        if (!samplers.is_null()) {
            b.doc["samplers"] = samplers;
            b.doc["textures"][0]["sampler"] = 0;
        }
        b.doc["materials"] = {{{"name", "leaf"}, {"pbrMetallicRoughness", {{"baseColorTexture", textureInfo}}}}};
        firstPrimitive(b)["material"] = 0;
    };
}
QuadEdit withTransform(const json& transform) {
    return withTexture({{"extensions", {{"KHR_texture_transform", transform}}}});
}
// Material 'glass' of `alphaMode` with extras {"shadow_alpha_cutoff": cutoff}.
QuadEdit withShadowAlphaCutoff(const char* alphaMode, const json& cutoff) {
    return set("/materials", {{{"name", "glass"}, {"alphaMode", alphaMode}, {"extras", {{"shadow_alpha_cutoff", cutoff}}}}});
}
// Material 'lamp' with KHR_materials_emissive_strength {"emissiveStrength": strength}.
QuadEdit withEmissiveStrength(const json& strength) {
    return set("/materials", {{{"name", "lamp"}, {"emissiveFactor", {1, 1, 1}},
                               {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}}});
}
// Material 'stone' on the quad with its textureInfo `key` (e.g. "occlusionTexture") set to
// `textureInfo` (index 0 added), of texture 0 (no image needed).
QuadEdit withMaterialTexture(const char* key, json textureInfo) {
    return [key, textureInfo](GltfBuilder& b) mutable {
        textureInfo["index"] = 0;
        b.doc["textures"] = {json::object()};
        b.doc["materials"] = {{{"name", "stone"}, {key, textureInfo}}};
        firstPrimitive(b)["material"] = 0;
    };
}
// The quad's TANGENT (VEC4 floats) and, optionally, one morph target moving its tangents by
// `targetOffsets` (floats of `targetType`, VEC3 for a valid file).
QuadEdit tangents(const std::vector<float>& values, const std::vector<float>& targetOffsets = {},
                  const char* targetType = "VEC3") {
    return [=](GltfBuilder& b) {
        firstPrimitive(b)["attributes"]["TANGENT"] = b.addFloats(values, 4, "VEC4");
        if (targetOffsets.empty()) return;
        const std::size_t components = std::string(targetType) == "VEC4" ? 4 : 3;
        firstPrimitive(b)["targets"] = json::array({{{"TANGENT", b.addFloats(targetOffsets, components, targetType)}}});
    };
}
const std::vector<float> kTangentsAlongX = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
// A vertex attribute of 4 elements of `type`, from raw bytes.
QuadEdit rawAttribute(const char* name, std::vector<std::uint8_t> bytes, int componentType, const char* type,
                      bool normalized, std::size_t count = 4) {
    return [=](GltfBuilder& b) {
        firstPrimitive(b)["attributes"][name] = b.addAccessor(b.addView(bytes.data(), bytes.size()), componentType, count,
                                                              type, normalized);
    };
}
QuadEdit floatAttribute(const char* name, const std::vector<float>& values, std::size_t components, const char* type) {
    return [=](GltfBuilder& b) { firstPrimitive(b)["attributes"][name] = b.addFloats(values, components, type); };
}
const char* const kTransformPath = "pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform";

// One image 'albedo' stored in a bufferView.
QuadEdit withImage(const std::vector<std::uint8_t>& encoded) {
    return [encoded](GltfBuilder& b) {
        b.doc["images"] = {{{"name", "albedo"}, {"bufferView", b.addView(encoded.data(), encoded.size())},
                            {"mimeType", "image/png"}}};
    };
}

const std::vector<std::uint8_t>& kTinyPng = tinyPng();  // gltf_test_support.h

std::vector<std::uint8_t> pngWithUndecodablePixels() {
    std::vector<std::uint8_t> png = kTinyPng;
    png[41] = 0x00;  // zlib header byte: the header still reads, the pixels do not
    png[42] = 0x00;
    return png;
}
std::vector<std::uint8_t> pngCutInItsHeader() { return {kTinyPng.begin(), kTinyPng.begin() + 12}; }
std::vector<std::uint8_t> gif() {
    const std::string gif = "GIF89a\x01\x00\x01\x00\x00\x00\x00;";
    return {gif.begin(), gif.end()};
}
std::vector<std::uint8_t> pngOf100000x1Pixels() {
    std::vector<std::uint8_t> png = kTinyPng;
    setU32(png, 16, 0xA0860100);  // big-endian 100000
    return png;
}

json nestedArrays(int depth) {
    json deep = json::array();
    for (int i = 0; i < depth; ++i) deep = json::array({deep});
    return deep;
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// The quad scene (gltf_test_support.h) edited in one place.
const std::vector<BadInputCase<QuadEdit>> kQuadEdits = {
    // Containers and JSON
    {"DeepJsonNestingInsideGlb", set("/extras", nestedArrays(100)),
     {"deep.glb", "JSON", "nesting deeper than 64 levels"}},
    {"UnsupportedAssetVersion", set("/asset/version", "1.0"),
     {"old.gltf", "asset", "version '1.0' is not supported"}},
    // An extension the engine has no decoder library for (WebP images).
    {"UnsupportedRequiredExtension", set("/extensionsRequired", {"KHR_lights_punctual", "EXT_texture_webp"}),
     {"webp.gltf", "extensionsRequired", "'EXT_texture_webp' is not supported",
      "(supported: KHR_lights_punctual, KHR_texture_transform, KHR_lights_shadows, KHR_draco_mesh_compression, "
      "EXT_meshopt_compression, KHR_mesh_quantization, KHR_materials_emissive_strength)"}},
    {"TinygltfErrorsArePassedOn", set("/accessors/0/type", "VEC5"),
     {"vec5.gltf", "tinygltf", "VEC5"}},
    // tinygltf 2.7.0 throws std::out_of_range here.
    {"GlbBufferWithByteLengthZeroDoesNotAbort", set("/buffers", {{{"byteLength", 0}}}),
     {"empty.glb", "buffers[0]", "byteLength is 0"}},
    {"GlbBufferLongerThanTheBinChunk",
     [](GltfBuilder& b) { b.doc["buffers"] = {{{"byteLength", b.bin.size() + 100}}}; },
     {"short.glb", "buffers[0]", "more than the GLB BIN chunk holds"}},

    // URIs and files
    {"MissingBufferFile", bufferUri("missing.bin"),
     {"nobin.gltf", "buffers[0]", "uri 'missing.bin'", "no such file"}},
    {"ImageUriLeadingOutIsRefused", set("/images", {{{"uri", "/etc/passwd"}}}),
     {"image.gltf", "images[0]", "is an absolute path"}},
    {"DataUriShorterThanByteLength",
     [](GltfBuilder& b) {
         const std::string uri = "data:application/octet-stream;base64," + base64(b.bin);
         b.doc["buffers"] = {{{"byteLength", b.bin.size() + 3}, {"uri", uri}}};
     },
     {"datauri.gltf", "buffers[0]", "data URI holds 60 bytes, byteLength says 63"}},
    {"ImageFileMissing", set("/images", {{{"uri", "albedo.png"}}}),
     {"noimage.gltf", "images[0]", "uri 'albedo.png'", "no such file"}},

    // Binary layout
    {"AccessorRunsPastItsView", set("/accessors/0/count", 5),
     {"past.gltf", "accessors[0]", "runs past the end of bufferViews[0] (needs 60 bytes, has 48)"}},
    {"AccessorOffsetRunsPastItsView", set("/accessors/0/byteOffset", 4),
     {"offset.gltf", "accessors[0]", "runs past the end of bufferViews[0] (needs 52 bytes, has 48)"}},
    {"BufferViewRunsPastItsBuffer", set("/bufferViews/1/byteLength", 1000),
     {"view.gltf", "bufferViews[1]", "runs past the end of buffers[0] (needs 1048 bytes, has 60)"}},
    {"ByteStrideNotAMultipleOf4", set("/bufferViews/0/byteStride", 14),
     {"stride.gltf", "bufferViews[0]", "byteStride 14"}},
    {"ByteStrideAbove252", set("/bufferViews/0/byteStride", 256),
     {"stride.gltf", "bufferViews[0]", "byteStride 256"}},
    {"ByteStrideSmallerThanTheElement", set("/bufferViews/0/byteStride", 8),
     {"stride.gltf", "accessors[0]", "byteStride 8 is smaller than the element size 12"}},
    {"CountZero", set("/accessors/0/count", 0),
     {"zero.gltf", "accessors[0]", "count is 0"}},
    {"SparseAccessorsAreRefused",
     set("/accessors/0/sparse", {{"count", 1},
                                 {"indices", {{"bufferView", 1}, {"componentType", kUnsignedShort}}},
                                 {"values", {{"bufferView", 0}}}}),
     {"sparse.gltf", "accessors[0]", "sparse accessors are not supported"}},
    {"AttributeOfTheWrongType",
     [](GltfBuilder& b) {
         b.doc["accessors"][0]["type"] = "VEC2";
         b.doc["accessors"][0]["count"] = 6;
     },
     {"type.gltf", "accessors[0]", "used as POSITION of meshes[0].primitives[0], must be VEC3"}},

    // Values
    {"IndexPastTheVertexCount", indices({0, 1, 2, 0, 2, 7}),
     {"index.gltf", "accessors[2]", "index 7 (element 5) is past the vertex count 4"}},
    {"NaNPosition", attribute("POSITION", {0, 0, 0, 1, 0, 0, 1, kNaN, 0, 0, 1, 0}),
     {"nan.gltf", "accessors[2]", "POSITION", "element 2", "not a finite number"}},
    {"InfiniteNormal", attribute("NORMAL", {0, 0, 1, 0, 0, 1, 0, 0, kInf, 0, 0, 1}),
     {"inf.gltf", "accessors[2]", "NORMAL", "not a finite number"}},
    {"TriangleListNotAMultipleOf3", indices({0, 1, 2, 0}),
     {"partial.gltf", "meshes[0].primitives[0]", "not a multiple of 3"}},
    {"NodeMatrixOfWrongLength", set("/nodes/0/matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0}),
     {"matrix.gltf", "nodes[0] 'Quad'", "matrix has 15 numbers, not 16"}},
    {"ZeroQuaternion", set("/nodes/0/rotation", {0, 0, 0, 0}),
     {"quat.gltf", "nodes[0] 'Quad'", "rotation is a zero quaternion"}},

    // Graph and references
    {"NodeCycle", withNodes({{{"name", "A"}, {"children", {2}}}, {{"name", "B"}, {"children", {1}}}}),
     {"cycle.gltf", "nodes[", "is its own ancestor"}},
    {"NodeThatIsItsOwnChild", set("/nodes/0/children", {0}),
     {"self.gltf", "nodes[0] 'Quad'", "lists itself as a child"}},
    {"NodeWithTwoParents", withNodes({{{"name", "P1"}, {"children", {0}}}, {{"name", "P2"}, {"children", {0}}}}, {1, 2}),
     {"parents.gltf", "nodes[0] 'Quad'", "has two parents: nodes[1] 'P1' and nodes[2] 'P2'"}},
    {"SceneRootThatIsAChild", withNodes({{{"name", "Parent"}, {"children", {0}}}}, {0, 1}),
     {"root.gltf", "scenes[0]", "is a child of nodes[1] 'Parent'"}},
    {"SceneRootIndexOutOfRange", withNodes({}, {0, 9}),
     {"roots.gltf", "scenes[0]", "node 9 does not exist"}},
    {"ChildIndexOutOfRange", set("/nodes/0/children", {5}),
     {"child.gltf", "nodes[0] 'Quad'", "child node 5 does not exist"}},

    // Property types (tinygltf 2.7.0 would silently skip these)
    {"PrimitivesThatAreNotAnArray",
     [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"] = {{"not an array", firstPrimitive(b)}}; },
     {"types.gltf", "meshes[0].primitives", "is not an array"}},
    {"NegativeIndex", set("/nodes/0/children", {-1}),
     {"types.gltf", "nodes[0].children", "is not an array of non-negative integers"}},
    {"AttributeIndexThatIsAString", set("/meshes/0/primitives/0/attributes/POSITION", "0"),
     {"types.gltf", "meshes[0].primitives[0].attributes.POSITION", "is not a non-negative integer"}},
    {"MeshIndexOutOfRange", set("/nodes/0/mesh", 3),
     {"mesh.gltf", "nodes[0] 'Quad'", "mesh 3 does not exist"}},
    {"MaterialIndexOutOfRange", set("/meshes/0/primitives/0/material", 0),
     {"material.gltf", "meshes[0].primitives[0]", "material 0 does not exist"}},
    {"CameraIndexOutOfRange", set("/nodes/0/camera", 0),
     {"camera.gltf", "nodes[0] 'Quad'", "camera 0 does not exist"}},
    {"CameraWithBadValues",
     set("/cameras", {{{"name", "eye"}, {"type", "perspective"},
                       {"perspective", {{"yfov", 0.8}, {"znear", 1.0}, {"zfar", 0.5}}}}}),
     {"camera.gltf", "cameras[0] 'eye'", "perspective.zfar 0.5 must be a finite number > znear"}},

    // Lights and extras
    {"LightOfUnknownType", withLight({{"name", "sun"}, {"type", "area"}}),
     {"light.gltf", "KHR_lights_punctual.lights[0] 'sun'", "type 'area' is not directional, point or spot"}},
    {"LightWithNegativeIntensity", withLight({{"type", "point"}, {"intensity", -1}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "intensity -1 is not a finite number >= 0"}},
    {"LightWithNegativeColor", withLight({{"type", "point"}, {"color", {1, -0.5, 1}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "color[1] -0.5 is not a finite number >= 0"}},
    {"LightColorOfTwoNumbers", withLight({{"type", "point"}, {"color", {1, 1}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "color is not an array of 3 numbers"}},
    {"LightWithZeroRange", withLight({{"type", "spot"}, {"range", 0}, {"spot", json::object()}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "range 0 is not a finite number > 0"}},
    {"SpotInnerAngleNotBelowOuter",
     withLight({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "spot.innerConeAngle 0.5 is not below outerConeAngle 0.5"}},
    {"SpotOuterAngleAboveHalfPi", withLight({{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "spot.outerConeAngle 2 is more than pi/2"}},
    {"SpotLightWithoutSpot", withLight({{"type", "spot"}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "spot is missing"}},
    {"LightExtrasNotAnObject", withLight({{"type", "point"}, {"extras", 5}}),
     {"light.gltf", "KHR_lights_punctual.lights[0]", "extras is not an object"}},
    {"NodeLightIndexOutOfRange", set("/nodes/0/extensions", {{"KHR_lights_punctual", {{"light", 4}}}}),
     {"light.gltf", "nodes[0] 'Quad'", "KHR_lights_punctual light 4 does not exist"}},
    {"NodeLightReferenceNotAnInteger", set("/nodes/0/extensions", {{"KHR_lights_punctual", {{"light", "sun"}}}}),
     {"light.gltf", "nodes[0] 'Quad'", "KHR_lights_punctual.light is missing or not an integer"}},
    {"ShadowExtraThatIsNotABoolean", set("/nodes/0/extras", {{"cast_shadows", "no"}}),
     {"extras.gltf", "nodes[0] 'Quad'", "extras.cast_shadows is not a boolean (true, false, or Blender's 1 or 0)"}},
    {"ShadowExtraThatIsANumberOtherThanZeroOrOne", set("/nodes/0/extras", {{"receive_shadows", 2}}),
     {"extras.gltf", "nodes[0] 'Quad'", "extras.receive_shadows is not a boolean"}},
    {"UnknownAlphaMode", set("/materials", {{{"name", "glass"}, {"alphaMode", "TRANSLUCENT"}}}),
     {"alpha.gltf", "materials[0] 'glass'", "alphaMode 'TRANSLUCENT' is not OPAQUE, MASK or BLEND"}},

    // Samplers, texture references, KHR_texture_transform, shadow_alpha_cutoff
    {"SamplerMagFilterThatIsAMinFilter", withTexture(json::object(), {{{"name", "pixel"}, {"magFilter", 9984}}}),
     {"sampler.gltf", "samplers[0] 'pixel'", "magFilter 9984 is not one of 9728, 9729"}},
    {"SamplerMinFilterUnknown", withTexture(json::object(), {{{"minFilter", 1234}}}),
     {"sampler.gltf", "samplers[0]", "minFilter 1234 is not one of 9728, 9729, 9984, 9985, 9986, 9987"}},
    {"SamplerWrapSUnknown", withTexture(json::object(), {{{"wrapS", 10496}}}),
     {"sampler.gltf", "samplers[0]", "wrapS 10496 is not one of 33071, 33648, 10497"}},
    {"SamplerWrapTThatIsAString", withTexture(json::object(), {{{"wrapT", "REPEAT"}}}),
     {"sampler.gltf", "samplers[0]", "wrapT is not an integer"}},
    {"TextureSamplerIndexOutOfRange", [](GltfBuilder& b) { withTexture(json::object())(b); b.doc["textures"][0]["sampler"] = 2; },
     {"sampler.gltf", "textures[0]", "sampler 2 does not exist (there are 0)"}},
    {"TexCoordThatIsNotAnInteger", withTexture({{"texCoord", 0.5}}),
     {"texcoord.gltf", "materials[0].pbrMetallicRoughness.baseColorTexture.texCoord", "is not a non-negative integer"}},
    {"TextureTransformNotAnObject", withTransform("Not an object"),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + " is not an object"}},
    {"TextureInfoExtensionsNotAnObject", withTexture({{"extensions", {1, 2}}}),
     {"transform.gltf", "materials[0] 'leaf'", "pbrMetallicRoughness.baseColorTexture.extensions is not an object"}},
    {"TextureTransformOffsetOfThreeNumbers", withTransform({{"offset", {0, 1, 2}}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".offset is not an array of 2 finite numbers"}},
    {"TextureTransformScaleBeyondFloat", withTransform({{"scale", {1, 1e39}}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".scale is not an array of 2 finite numbers"}},
    {"TextureTransformOffsetOfStrings", withTransform({{"offset", {"0", "1"}}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".offset is not an array of 2 finite numbers"}},
    {"TextureTransformRotationThatIsAString", withTransform({{"rotation", "90deg"}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".rotation is not a number"}},
    {"TextureTransformRotationBeyondFloat", withTransform({{"rotation", -1e300}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".rotation -1e+300 is not a finite (float) number"}},
    {"TextureTransformNegativeTexCoord", withTransform({{"texCoord", -1}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".texCoord is not a non-negative integer"}},
    {"TextureTransformFractionalTexCoord", withTransform({{"texCoord", 1.5}}),
     {"transform.gltf", "materials[0] 'leaf'", std::string(kTransformPath) + ".texCoord is not a non-negative integer"}},
    {"ShadowAlphaCutoffOnAMaskMaterial", withShadowAlphaCutoff("MASK", 0.3),
     {"cutoff.gltf", "materials[0] 'glass'", "extras.shadow_alpha_cutoff is only for alphaMode BLEND",
      "MASK material casts by its alphaCutoff"}},
    {"ShadowAlphaCutoffOnAnOpaqueMaterial", withShadowAlphaCutoff("OPAQUE", 0.3),
     {"cutoff.gltf", "materials[0] 'glass'", "extras.shadow_alpha_cutoff is only for alphaMode BLEND",
      "OPAQUE material casts solid"}},
    {"ShadowAlphaCutoffThatIsAString", withShadowAlphaCutoff("BLEND", "0.5"),
     {"cutoff.gltf", "materials[0] 'glass'", "extras.shadow_alpha_cutoff is not a number"}},
    {"NegativeShadowAlphaCutoff", withShadowAlphaCutoff("BLEND", -0.25),
     {"cutoff.gltf", "materials[0] 'glass'", "extras.shadow_alpha_cutoff -0.25 is not >= 0"}},
    {"NegativeEmissiveStrength", withEmissiveStrength(-2.0),
     {"emissive.gltf", "materials[0] 'lamp'", "extensions.KHR_materials_emissive_strength.emissiveStrength -2 is not >= 0"}},
    {"EmissiveStrengthThatIsAString", withEmissiveStrength("bright"),
     {"emissive.gltf", "materials[0] 'lamp'", "extensions.KHR_materials_emissive_strength.emissiveStrength is not a number"}},

    // The other material textures: occlusion strength, normal scale, their textureInfo
    {"OcclusionStrengthAboveOne", withMaterialTexture("occlusionTexture", {{"strength", 1.5}}),
     {"strength.gltf", "materials[0] 'stone'", "occlusionTexture.strength 1.5 is not in [0, 1]"}},
    {"NegativeOcclusionStrength", withMaterialTexture("occlusionTexture", {{"strength", -0.25}}),
     {"strength.gltf", "materials[0] 'stone'", "occlusionTexture.strength -0.25 is not in [0, 1]"}},
    {"OcclusionStrengthThatIsAString", withMaterialTexture("occlusionTexture", {{"strength", "full"}}),
     {"strength.gltf", "materials[0] 'stone'", "occlusionTexture.strength is not a number"}},
    // JSON has no infinity: beyond float range is how a file says it.
    {"NormalScaleBeyondFloat", withMaterialTexture("normalTexture", {{"scale", -1e39}}),
     {"scale.gltf", "materials[0] 'stone'", "normalTexture.scale -1e+39 is not a finite (float) number"}},
    {"NormalScaleThatIsAString", withMaterialTexture("normalTexture", {{"scale", "2"}}),
     {"scale.gltf", "materials[0] 'stone'", "normalTexture.scale is not a number"}},
    {"NormalTextureTexCoordNotAnInteger", withMaterialTexture("normalTexture", {{"texCoord", "1"}}),
     {"texcoord.gltf", "materials[0] 'stone'", "normalTexture.texCoord is not a non-negative integer"}},
    {"EmissiveTextureTransformRotationThatIsAString",
     withMaterialTexture("emissiveTexture", {{"extensions", {{"KHR_texture_transform", {{"rotation", "90deg"}}}}}}),
     {"transform.gltf", "materials[0] 'stone'", "emissiveTexture.extensions.KHR_texture_transform.rotation is not a number"}},

    // TANGENT and its morph offsets
    {"TangentWithNaN", tangents({1, 0, 0, 1, 1, 0, 0, 1, kNaN, 0, 0, 1, 1, 0, 0, 1}),
     {"tangent.gltf", "accessors[2]", "used as TANGENT of meshes[0].primitives[0]", "element 2", "not a finite number"}},
    {"TangentWithInfiniteW", tangents({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -kInf}),
     {"tangent.gltf", "accessors[2]", "used as TANGENT of meshes[0].primitives[0]", "element 3", "not a finite number"}},
    {"TangentWithWOfHalf", tangents({1, 0, 0, 1, 1, 0, 0, 0.5f, 1, 0, 0, 1, 1, 0, 0, 1}),
     {"tangent.gltf", "meshes[0].primitives[0]", "TANGENT of vertex 1 has w 0.5, not +1 or -1"}},
    {"TangentWithWOfZero", tangents({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 0}),
     {"tangent.gltf", "meshes[0].primitives[0]", "TANGENT of vertex 3 has w 0, not +1 or -1"}},
    {"TangentOfVec3", floatAttribute("TANGENT", {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0}, 3, "VEC3"),
     {"tangent.gltf", "accessors[2]", "used as TANGENT of meshes[0].primitives[0]",
      "must be VEC4 of FLOAT or normalized BYTE/SHORT, but is VEC3 of FLOAT"}},
    {"TangentOfUnsignedBytes", rawAttribute("TANGENT", std::vector<std::uint8_t>(16, 1), kUnsignedByte, "VEC4", true),
     {"tangent.gltf", "accessors[2]", "used as TANGENT of meshes[0].primitives[0]", "but is VEC4 of normalized UNSIGNED_BYTE"}},
    {"TangentOfTheWrongCount", floatAttribute("TANGENT", {1, 0, 0, 1, 1, 0, 0, 1}, 4, "VEC4"),
     {"tangent.gltf", "meshes[0].primitives[0]", "TANGENT has 2 elements, POSITION has 4"}},
    {"MorphTargetTangentWithNaN", tangents(kTangentsAlongX, {0, 1, 0, 0, 1, 0, 0, kNaN, 0, 0, 1, 0}),
     {"tangent.gltf", "accessors[3]", "used as targets[0] TANGENT of meshes[0].primitives[0]", "element 2",
      "not a finite number"}},
    {"MorphTargetTangentOfVec4", tangents(kTangentsAlongX, {0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, "VEC4"),
     {"tangent.gltf", "accessors[3]", "used as targets[0] TANGENT of meshes[0].primitives[0]",
      "must be VEC3 of FLOAT or normalized BYTE/SHORT, but is VEC4 of FLOAT"}},

    // TEXCOORD_1, COLOR_0
    {"Texcoord1OfTheWrongCount", floatAttribute("TEXCOORD_1", {0, 0, 1, 0, 1, 1}, 2, "VEC2"),
     {"uv1.gltf", "meshes[0].primitives[0]", "TEXCOORD_1 has 3 elements, POSITION has 4"}},
    // KHR_mesh_quantization allows 8- and 16-bit texture coordinates, normalized or not; not 32-bit.
    {"Texcoord1OfUnsignedInt", rawAttribute("TEXCOORD_1", std::vector<std::uint8_t>(32, 0), kUnsignedInt, "VEC2", false),
     {"uv1.gltf", "accessors[2]", "used as TEXCOORD_1 of meshes[0].primitives[0]",
      "must be VEC2 of FLOAT or (UNSIGNED_)BYTE/(UNSIGNED_)SHORT, but is VEC2 of UNSIGNED_INT"}},
    {"Texcoord1WithNaN", floatAttribute("TEXCOORD_1", {0, 0, 1, 0, 1, kNaN, 0, 1}, 2, "VEC2"),
     {"uv1.gltf", "accessors[2]", "TEXCOORD_1", "element 2", "not a finite number"}},
    {"Color0OfVec2", floatAttribute("COLOR_0", {1, 1, 1, 1, 1, 1, 1, 1}, 2, "VEC2"),
     {"color.gltf", "accessors[2]", "used as COLOR_0 of meshes[0].primitives[0]",
      "must be VEC3 or VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT, but is VEC2 of FLOAT"}},
    {"Color0OfBytesNotNormalized",
     rawAttribute("COLOR_0", std::vector<std::uint8_t>(16, 255), kUnsignedByte, "VEC4", false),
     {"color.gltf", "accessors[2]", "used as COLOR_0 of meshes[0].primitives[0]", "but is VEC4 of UNSIGNED_BYTE"}},
    {"Color0OfTheWrongCount", floatAttribute("COLOR_0", {1, 1, 1, 1, 1, 1}, 3, "VEC3"),
     {"color.gltf", "meshes[0].primitives[0]", "COLOR_0 has 2 elements, POSITION has 4"}},
    {"Color0WithInfinity", floatAttribute("COLOR_0", {1, 1, 1, 1, 1, 1, 1, 1, kInf, 1, 1, 1}, 3, "VEC3"),
     {"color.gltf", "accessors[2]", "COLOR_0", "element 2", "not a finite number"}},

    // KHR_lights_shadows
    {"PrimitiveLightsShadowsNotAnObject", set("/meshes/0/primitives/0/extensions", {{"KHR_lights_shadows", true}}),
     {"shadows.gltf", "meshes[0].primitives[0]", "extensions.KHR_lights_shadows is not an object"}},
    {"PrimitiveCastShadowsNotABoolean",
     set("/meshes/0/primitives/0/extensions", {{"KHR_lights_shadows", {{"castShadows", 0}}}}),
     {"shadows.gltf", "meshes[0].primitives[0]", "extensions.KHR_lights_shadows.castShadows is not a boolean"}},
    {"PrimitiveReceiveShadowsNotABoolean",
     set("/meshes/0/primitives/0/extensions", {{"KHR_lights_shadows", {{"receiveShadows", "false"}}}}),
     {"shadows.gltf", "meshes[0].primitives[0]", "extensions.KHR_lights_shadows.receiveShadows is not a boolean"}},
    {"PrimitiveExtensionsNotAnObject", set("/meshes/0/primitives/0/extensions", "KHR_lights_shadows"),
     {"shadows.gltf", "meshes[0].primitives[0]", "extensions is not an object"}},
    {"LightCastShadowsNotABoolean",
     withLight({{"name", "sun"}, {"type", "directional"}, {"extensions", {{"KHR_lights_shadows", {{"castShadows", "no"}}}}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0] 'sun'", "extensions.KHR_lights_shadows.castShadows is not a boolean"}},
    {"LightLightsShadowsNotAnObject",
     withLight({{"name", "sun"}, {"type", "directional"}, {"extensions", {{"KHR_lights_shadows", {false}}}}}),
     {"light.gltf", "KHR_lights_punctual.lights[0] 'sun'", "extensions.KHR_lights_shadows is not an object"}},

    // Images
    {"ImageWhosePixelsFailToDecode", withImage(pngWithUndecodablePixels()),
     {"broken.glb", "images[0] 'albedo'", "failed to decode"}},
    {"ImageWithUnreadableHeader", withImage(pngCutInItsHeader()),
     {"header.glb", "images[0] 'albedo'", "cannot read the image header"}},
    {"ImageThatIsNeitherPngNorJpeg", withImage(gif()),
     {"gif.glb", "images[0] 'albedo'", "is not a PNG or JPEG file (mimeType image/png)"}},
    {"ImageLargerThanTheLimitIsRefusedBeforeDecoding", withImage(pngOf100000x1Pixels()),
     {"bomb.glb", "images[0] 'albedo'", "100000x1 pixels is outside 1..8192"}},
};

// The quad scene's GLB bytes edited in one place.
const std::vector<BadInputCase<GlbByteEdit>> kGlbByteEdits = {
    {"TruncatedGlb", [](std::vector<std::uint8_t>& glb) { glb.resize(glb.size() - 10); },
     {"cut.glb", "GLB header", "truncated", "the file has"}},
    {"GlbCutInsideItsHeader", [](std::vector<std::uint8_t>& glb) { glb.resize(7); },
     {"stub.glb", "GLB header", "truncated"}},
    {"GlbJsonChunkLengthLies", [](std::vector<std::uint8_t>& glb) { setU32(glb, 12, 0x7FFFFFF0); },
     {"liar.glb", "GLB chunk 0 (JSON)", "runs past the end of the file"}},
    // tinygltf 2.7.0 forgets the BIN chunk's 8-byte header in its own check: a length 4
    // bytes too long would have it read past the end of the file.
    {"GlbBinChunkLengthLiesByLessThanItsHeader",
     [](std::vector<std::uint8_t>& glb) {
         std::uint32_t jsonLength;
         std::memcpy(&jsonLength, glb.data() + 12, 4);
         const std::size_t binHeader = 20 + jsonLength;
         std::uint32_t binLength;
         std::memcpy(&binLength, glb.data() + binHeader, 4);
         setU32(glb, binHeader, binLength + 4);
     },
     {"binliar.glb", "GLB chunk 1 (BIN)", "runs past the end of the file"}},
    {"GlbVersionOtherThan2", [](std::vector<std::uint8_t>& glb) { setU32(glb, 4, 1); },
     {"v1.glb", "GLB header", "version 1 is not supported"}},
    {"GlbLengthDisagreesWithFileSize", [](std::vector<std::uint8_t>& glb) { glb.insert(glb.end(), 16, 0); },
     {"long.glb", "GLB header", "but the file has"}},
};

class QuadEditTest : public ::testing::TestWithParam<BadInputCase<QuadEdit>> {};

TEST_P(QuadEditTest, IsRefusedNamingFileObjectAndReason) {
    const BadInputCase<QuadEdit>& c = GetParam();
    TempDir dir;
    GltfBuilder b = quadScene();
    c.edit(b);
    const fs::path file = c.message.at(0);
    const std::string stem = file.stem().string();
    expectLoadError(file.extension() == ".glb" ? b.writeGlb(dir.path(), stem) : b.writeGltf(dir.path(), stem), c.message);
}

INSTANTIATE_TEST_SUITE_P(GltfBadInput, QuadEditTest, ::testing::ValuesIn(kQuadEdits), CaseName());

class GlbByteEditTest : public ::testing::TestWithParam<BadInputCase<GlbByteEdit>> {};

TEST_P(GlbByteEditTest, IsRefusedNamingFileObjectAndReason) {
    const BadInputCase<GlbByteEdit>& c = GetParam();
    TempDir dir;
    std::vector<std::uint8_t> glb = quadScene().glbBytes();
    c.edit(glb);
    const fs::path file = dir / c.message.at(0);
    writeBytes(file, glb);
    expectLoadError(file, c.message);
}

INSTANTIATE_TEST_SUITE_P(GltfBadInput, GlbByteEditTest, ::testing::ValuesIn(kGlbByteEdits), CaseName());

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

// Debian's assimp-testmodels ships a file whose KHR_texture_transform is a string: tinygltf
// 2.7.0 drops it silently (an extension that is not an object is skipped), so the loader
// must see it in its own parse. tools/install-deps.sh installs the package: a missing file
// is a failure here, not a skip.
TEST(GltfBadInput, AssimpBadExtensionTextureTransformIsRefused) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    const fs::path file = engine::test::kAssimpGltf2Models / "wrongTypes/badExtension.gltf";
    expectLoadError(file, {"badExtension.gltf", "materials[0] 'Texture'",
                           "pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform is not an object"});
}

// --- URIs and files ----------------------------------------------------------------------

// The quad scene with its buffer's uri replaced (the .bin is still written next to it).
fs::path quadWithBufferUri(const fs::path& dir, const std::string& uri, const std::string& name) {
    GltfBuilder b = quadScene();
    bufferUri(uri)(b);
    return b.writeGltf(dir, name);
}

// A copy of the quad's buffer outside `dir`, so refusals cannot be blamed on a missing file.
struct OutsideFile {
    TempDir elsewhere;
    fs::path path = elsewhere / "secret.bin";
    OutsideFile() { writeBytes(path, quadScene().bin); }
};

// The scene in dir/scene, its buffer's uri naming dir/outside.bin (which exists).
fs::path quadInSubfolderWithBufferUri(const TempDir& dir, const std::string& uri, const std::string& name) {
    fs::create_directories(dir / "scene");
    writeBytes(dir / "outside.bin", quadScene().bin);
    return quadWithBufferUri(dir / "scene", uri, name);
}

TEST(GltfBadInput, DotDotUriIsRefused) {
    TempDir dir;
    expectLoadError(quadInSubfolderWithBufferUri(dir, "../outside.bin", "up"),
                    {"up.gltf", "buffers[0]", "climbs out of the scene's folder"});
}

TEST(GltfBadInput, PercentEncodedDotDotUriIsRefused) {
    TempDir dir;
    expectLoadError(quadInSubfolderWithBufferUri(dir, "%2e%2e/outside.bin", "encoded"),
                    {"encoded.gltf", "buffers[0]", "'%2e%2e/outside.bin' climbs out"});
}

TEST(GltfBadInput, AbsoluteUriIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    expectLoadError(quadWithBufferUri(dir.path(), outside.path.string(), "absolute"),
                    {"absolute.gltf", "buffers[0]", "is an absolute path"});
}

TEST(GltfBadInput, FileSchemeUriIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    expectLoadError(quadWithBufferUri(dir.path(), "file://" + outside.path.string(), "scheme"),
                    {"scheme.gltf", "buffers[0]", "has a scheme"});
}

TEST(GltfBadInput, SymlinkLeadingOutIsRefused) {
    TempDir dir;
    const OutsideFile outside;
    fs::create_symlink(outside.path, dir / "link.bin");
    expectLoadError(quadWithBufferUri(dir.path(), "link.bin", "symlink"),
                    {"symlink.gltf", "buffers[0]", "uri 'link.bin'", "outside the scene's folder"});
}

TEST(GltfBadInput, DirectoryAsUriIsRefused) {
    // tinygltf 2.7.0 would try to allocate 0x7fff... bytes and abort.
    TempDir dir;
    fs::create_directories(dir / "data.bin");
    expectLoadError(quadWithBufferUri(dir.path(), "data.bin", "dir"), {"dir.gltf", "buffers[0]", "is not a regular file"});
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

} // namespace
