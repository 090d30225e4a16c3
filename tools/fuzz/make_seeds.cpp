// Writes the fuzz seed corpus: make_seeds OUT_DIR SCENES_DIR
//   - every .gltf/.glb of SCENES_DIR (content/scenes: the showcase, the masked scenes and
//     their twins; their .bin files are next to the fuzzed file, gltf_fuzzer.cpp copies
//     them there),
//   - small self-contained scenes that together reach every feature the loader converts:
//     data-URI and GLB buffers, interleaved views, 8/16/32-bit indices, strips and fans,
//     points and lines (dropped), normalized texcoords, PNG and JPEG images from a data URI,
//     a bufferView and a file URI ('tex.png', also next to the fuzzed file), materials,
//     both camera types, KHR_lights_punctual, node hierarchies with TRS and matrices;
//     samplers, TEXCOORD_1, KHR_texture_transform, COLOR_0, KHR_lights_shadows and
//     shadow_alpha_cutoff; every material texture, TANGENT (read, with morph offsets, and
//     generated for a normal map); Draco and meshopt-compressed, quantized meshes
//     (compressed_seeds.h).
// Small on purpose: libFuzzer mutates short inputs much faster.
#include "compressed_seeds.h"
#include "gltf_writer.h"  // tests/unit/: the loader tests' glTF writer

#include <stb_image_write.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace gltf_writer;

std::vector<std::uint8_t> encodeImage(bool jpeg) {
    // 2x2 RGB: red, green, blue, white.
    const std::uint8_t pixels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    std::vector<std::uint8_t> out;
    const auto append = [](void* context, void* data, int size) {
        auto& bytes = *static_cast<std::vector<std::uint8_t>*>(context);
        bytes.insert(bytes.end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
    };
    if (jpeg) stbi_write_jpg_to_func(append, &out, 2, 2, 3, pixels, 90);
    else stbi_write_png_to_func(append, &out, 2, 2, 3, pixels, 2 * 3);
    return out;
}

// Every seed names its generator.
GltfBuilder seedBuilder() {
    GltfBuilder b;
    b.doc["asset"]["generator"] = "tools/fuzz/make_seeds";
    return b;
}

const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

// One indexed triangle: the smallest scene that loads and draws.
GltfBuilder triangle() {
    GltfBuilder b = seedBuilder();
    const int positions = b.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int indices = b.addIndices(std::vector<std::uint8_t>{0, 1, 2});
    b.addMesh({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    return b;
}

// A textured quad: NORMAL, normalized TEXCOORD_0, material, image in a bufferView (PNG or
// JPEG), a perspective camera on a TRS node.
GltfBuilder texturedQuad(bool jpeg) {
    GltfBuilder b = seedBuilder();
    const int positions = b.addPositions(kQuadPositions);
    const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, 3, "VEC3");
    // Two bytes of padding per vertex: glTF aligns every vertex attribute element to 4 bytes.
    const std::vector<std::uint8_t> uv = {0, 255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0};
    const int uvView = b.addView(uv.data(), uv.size(), /*stride=*/4);
    const int texcoords = b.addAccessor(uvView, kUnsignedByte, 4, "VEC2", /*normalized=*/true);
    const int indices = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    const std::vector<std::uint8_t> image = encodeImage(jpeg);
    const int imageView = b.addView(image.data(), image.size());
    b.add("images", {{"bufferView", imageView}, {"mimeType", jpeg ? "image/jpeg" : "image/png"}});
    b.add("samplers", {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 33648}});
    b.add("textures", {{"source", 0}, {"sampler", 0}});
    b.add("materials", {{"name", "checker"},
                        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}},
                                                  {"baseColorFactor", {1, 0.5, 0.25, 1}},
                                                  {"metallicFactor", 0.1}, {"roughnessFactor", 0.7}}},
                        {"emissiveFactor", {0.1, 0, 0}}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.4},
                        {"doubleSided", true}});
    b.add("meshes", {{"name", "quad"},
                     {"primitives", {{{"attributes", {{"POSITION", positions}, {"NORMAL", normals},
                                                      {"TEXCOORD_0", texcoords}}},
                                      {"indices", indices}, {"material", 0}, {"mode", 4}}}}});
    b.add("cameras", {{"type", "perspective"},
                      {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}, {"aspectRatio", 1.5}}}});
    b.add("nodes", {{"name", "quad"}, {"mesh", 0}, {"translation", {1, 2, 3}},
                    {"rotation", {0, 0.38268343, 0, 0.92387953}}, {"scale", {2, 2, 2}}});
    b.add("nodes", {{"name", "camera"}, {"camera", 0}, {"translation", {0, 0, 5}}});
    b.doc["scenes"] = json::array({{{"name", "main"}, {"nodes", {0, 1}}}});
    b.doc["scene"] = 0;
    return b;
}

// Lights, a hierarchy with matrix and TRS nodes, an orthographic camera, extras, an image
// from a file URI and one from a data URI, a second scene.
GltfBuilder lightsAndHierarchy() {
    GltfBuilder b = seedBuilder();
    const int positions = b.addPositions(kQuadPositions);
    const int texcoords = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, 2, "VEC2");  // the texture needs them
    const int indices = b.addIndices(std::vector<std::uint32_t>{0, 1, 2, 2, 3, 0});
    b.add("images", {{"uri", "tex.png"}, {"name", "file"}});
    b.add("images", {{"uri", "data:image/png;base64," + base64(encodeImage(false))}});
    b.add("textures", {{"source", 0}});
    b.add("textures", {{"source", 1}});
    b.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}, {"alphaMode", "BLEND"}});
    b.add("meshes", {{"primitives", {{{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", texcoords}}},
                                      {"indices", indices}, {"material", 0}}}}});
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "spot"}, {"type", "spot"}, {"color", {1, 0.9, 0.8}}, {"intensity", 100}, {"range", 20},
         {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}},
         {"extras", {{"shadow", {{"variant", "standard"}, {"resolution", 1024}, {"filter", "pcf"}}}}}},
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 2}},
        {{"name", "bulb"}, {"type", "point"}, {"range", 5}},
    };
    const auto light = [](int index) { return json{{"KHR_lights_punctual", {{"light", index}}}}; };
    b.add("cameras", {{"type", "orthographic"},
                      {"orthographic", {{"xmag", 2}, {"ymag", 1}, {"znear", 0.01}, {"zfar", 50}}}});
    b.add("nodes", {{"name", "root"}, {"children", {1, 2, 3}},
                    {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1}}});
    b.add("nodes", {{"name", "floor"}, {"mesh", 0}, {"extras", {{"cast_shadows", false}, {"receive_shadows", true}}}});
    b.add("nodes", {{"name", "spot"}, {"extensions", light(0)}, {"translation", {0, 5, 0}},
                    {"rotation", {-0.70710678, 0, 0, 0.70710678}}, {"children", {4}}});
    b.add("nodes", {{"name", "sun"}, {"extensions", light(1)}});
    b.add("nodes", {{"name", "bulb"}, {"extensions", light(2)}, {"camera", 0}, {"scale", {1, 1, 1}}});
    b.add("nodes", {{"name", "other"}, {"mesh", 0}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {5}}}});
    b.doc["scene"] = 1;
    return b;
}

// Strips, fans, points and lines; an interleaved view (byteStride); accessor byteOffsets;
// no scenes (every root is shown).
GltfBuilder primitiveModes() {
    GltfBuilder b = seedBuilder();
    // x y z nx ny nz per vertex, interleaved.
    const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1,
                                            1, 1, 0, 0, 0, 1, 0, 2, 0, 0, 0, 1};
    const int view = b.addView(interleaved.data(), interleaved.size() * sizeof(float), 24);
    const int positions = b.addAccessor(view, kFloat, 5, "VEC3");
    b.setBounds(positions, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0});
    const int normals = b.add("accessors", {{"bufferView", view}, {"byteOffset", 12}, {"componentType", kFloat},
                                            {"count", 5}, {"type", "VEC3"}});
    const int strip = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 3, 4});
    const int fan = b.addIndices(std::vector<std::uint32_t>{0, 1, 3, 2});
    const json attributes = {{"POSITION", positions}, {"NORMAL", normals}};
    b.add("meshes", {{"primitives", {{{"attributes", attributes}, {"indices", strip}, {"mode", 5}},
                                     {{"attributes", attributes}, {"indices", fan}, {"mode", 6}},
                                     {{"attributes", attributes}, {"mode", 0}},
                                     {{"attributes", attributes}, {"mode", 1}}}}});
    b.add("nodes", {{"mesh", 0}});
    b.add("nodes", {{"mesh", 0}, {"translation", {3, 0, 0}}});
    return b;
}

// What alpha-tested shadows read: a sampler, the base color texture on TEXCOORD_1 through
// KHR_texture_transform, COLOR_0 (VEC3 float and VEC4 normalized bytes), KHR_lights_shadows
// on primitives and on a light, and a BLEND material's shadow_alpha_cutoff.
GltfBuilder texturesColorsShadows() {
    GltfBuilder b = seedBuilder();
    const int positions = b.addPositions(kQuadPositions);
    const std::vector<std::uint16_t> uv = {0, 0, 65535, 0, 65535, 65535, 0, 65535};
    const int uv0 = b.addAccessor(b.addView(uv.data(), uv.size() * 2), kUnsignedShort, 4, "VEC2", true);
    const int uv1 = b.addFloats({0, 0, 2, 0, 2, 2, 0, 2}, 2, "VEC2");
    const int rgb = b.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, 3, "VEC3");
    const std::vector<std::uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 64, 255, 255, 255, 0};
    const int rgba8 = b.addAccessor(b.addView(rgba.data(), rgba.size()), kUnsignedByte, 4, "VEC4", true);
    const int indices = b.addIndices(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3});
    b.add("images", {{"uri", "tex.png"}});
    b.add("samplers", {{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33071}, {"wrapT", 33648}});
    b.add("textures", {{"source", 0}, {"sampler", 0}});
    const json transform = {{"offset", {0, 1}}, {"rotation", 1.5707963}, {"scale", {0.5, 0.5}}, {"texCoord", 1}};
    b.add("materials", {{"name", "pane"}, {"alphaMode", "BLEND"}, {"extras", {{"shadow_alpha_cutoff", 0.3}}},
                        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 0},
                                                                        {"extensions", {{"KHR_texture_transform", transform}}}}}}}});
    const json attributes = {{"POSITION", positions}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}};
    json first = {{"attributes", attributes}, {"indices", indices}, {"material", 0},
                  {"extensions", {{"KHR_lights_shadows", {{"castShadows", false}, {"receiveShadows", true}}}}}};
    first["attributes"]["COLOR_0"] = rgb;
    json second = {{"attributes", attributes}, {"indices", indices}, {"material", 0},
                   {"extensions", {{"KHR_lights_shadows", {{"receiveShadows", false}}}}}};
    second["attributes"]["COLOR_0"] = rgba8;
    b.add("meshes", {{"primitives", {first, second}}});
    b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_texture_transform", "KHR_lights_shadows"};
    b.doc["extensionsRequired"] = {"KHR_texture_transform"};
    b.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"extensions", {{"KHR_lights_shadows", {{"castShadows", false}}}}}}};
    b.add("nodes", {{"mesh", 0}});
    b.add("nodes", {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.setScene({0, 1});
    return b;
}

// Every material texture on a quad facing +z (metallic-roughness; normal with a scale,
// through KHR_texture_transform; occlusion with a strength; emissive), all of the image file
// 'tex.png'. Without TANGENT the loader generates the tangents; with it, it reads them,
// and a morph target turns them (TANGENT offsets) as it lifts the quad.
GltfBuilder normalMappedQuad(bool withTangents) {
    GltfBuilder b = seedBuilder();
    const int positions = b.addPositions(kQuadPositions);
    const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, 3, "VEC3");
    const int texcoords = b.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, 2, "VEC2");  // upright: v grows along -y
    const int indices = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    b.add("images", {{"uri", "tex.png"}});
    b.add("textures", {{"source", 0}});
    const json texture = {{"index", 0}};
    const json transform = {{"rotation", 0.5}, {"scale", {2, 2}}};
    b.add("materials", {{"name", "embossed"},
                        {"pbrMetallicRoughness", {{"metallicRoughnessTexture", texture}}},
                        {"normalTexture", {{"index", 0}, {"scale", 0.5},
                                           {"extensions", {{"KHR_texture_transform", transform}}}}},
                        {"occlusionTexture", {{"index", 0}, {"strength", 0.75}}},
                        {"emissiveTexture", texture},
                        {"emissiveFactor", {1, 1, 1}}});
    json primitive = {{"attributes", {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", texcoords}}},
                      {"indices", indices}, {"material", 0}};
    if (withTangents) {
        // +x, the last two vertices mirrored (w = -1); the target turns them toward +y.
        primitive["attributes"]["TANGENT"] =
            b.addFloats({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1, 1, 0, 0, -1}, 4, "VEC4");
        const int lift = b.addPositions({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
        const int turn = b.addFloats({-1, 1, 0, -1, 1, 0, -1, 1, 0, -1, 1, 0}, 3, "VEC3");
        primitive["targets"] = json::array({{{"POSITION", lift}, {"TANGENT", turn}}});
    }
    b.add("meshes", {{"name", "embossed"}, {"primitives", {primitive}}});
    if (withTangents) b.doc["meshes"][0]["weights"] = {0.5};
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    b.addNode({{"mesh", 0}});
    b.setScene({0});
    return b;
}

// An accessor without a bufferView (all zeros, glTF 2.0), alone so that the other seeds
// still load if the loader refuses these.
GltfBuilder zeroAccessor() {
    GltfBuilder b = triangle();
    b.doc["accessors"][0].erase("bufferView");
    b.setBounds(0, {0, 0, 0});  // what the accessor now holds
    return b;
}

// The triangle animated by every interpolation (gltf_writer.h), one of them reading
// normalized integers.
GltfBuilder animatedTriangle() {
    GltfBuilder b = triangle();
    addSlideTurnGrowAnimation(b, 0);
    return b;
}

// The skinned quad (gltf_writer.h) with a morph target lifting it, mesh weights, and an
// animation turning its tip joint and running the weights: skins, morphs and both channels.
GltfBuilder skinnedMorphedQuad() {
    GltfBuilder b = skinnedQuad();
    b.doc["asset"]["generator"] = "tools/fuzz/make_seeds";
    b.doc["nodes"][0].erase("translation");  // a valid file: a skinned node's transform is unused
    const int lift = b.addPositions({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    b.doc["meshes"][0]["primitives"][0]["targets"] = json::array({{{"POSITION", lift}}});
    b.doc["meshes"][0]["weights"] = {0.25};
    const int times = b.addFloats({0, 1}, 1, "SCALAR");
    b.doc["accessors"][times]["min"] = {0};
    b.doc["accessors"][times]["max"] = {1};
    const int turn = b.addFloats({0, 0, 0, 1, 0, 0, 0.70710678f, 0.70710678f}, 4, "VEC4");
    const int weights = b.addFloats({0, 1}, 1, "SCALAR");
    b.add("animations", {{"name", "BendAndLift"},
                         {"samplers", {{{"input", times}, {"output", turn}}, {{"input", times}, {"output", weights}}}},
                         {"channels",
                          {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                           {{"sampler", 1}, {"target", {{"node", 0}, {"path", "weights"}}}}}}});
    return b;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: make_seeds OUT_DIR SCENES_DIR\n");
        return 2;
    }
    const fs::path out = argv[1];
    fs::create_directories(out);
    for (const auto& entry : fs::directory_iterator(argv[2]))
        if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb")
            fs::copy_file(entry.path(), out / entry.path().filename(), fs::copy_options::overwrite_existing);

    // Buffers inline (data URIs), so every seed is one file.
    const auto gltf = [&](const GltfBuilder& b, const char* name) { writeText(out / name, b.gltfText(BufferStorage::DataUri)); };
    const auto glb = [&](const GltfBuilder& b, const char* name) { writeBytes(out / name, b.glbBytes()); };
    try {
        writeText(out / "minimal.gltf", R"({"asset":{"version":"2.0"}})");
        gltf(triangle(), "triangle.gltf");
        glb(triangle(), "triangle.glb");
        glb(texturedQuad(false), "quad-png.glb");
        glb(texturedQuad(true), "quad-jpeg.glb");
        gltf(texturedQuad(false), "quad-png.gltf");
        gltf(lightsAndHierarchy(), "lights.gltf");
        glb(lightsAndHierarchy(), "lights.glb");
        glb(primitiveModes(), "modes.glb");
        gltf(primitiveModes(), "modes.gltf");
        gltf(zeroAccessor(), "zeros.gltf");
        gltf(texturesColorsShadows(), "textures-colors-shadows.gltf");
        glb(texturesColorsShadows(), "textures-colors-shadows.glb");
        gltf(compressed_seeds::dracoCube(), "draco-cube.gltf");
        glb(compressed_seeds::dracoCube(), "draco-cube.glb");
        glb(compressed_seeds::meshoptQuad(), "meshopt-quad.glb");
        gltf(animatedTriangle(), "animated.gltf");
        glb(animatedTriangle(), "animated.glb");
        gltf(skinnedMorphedQuad(), "skinned-morphed.gltf");
        gltf(normalMappedQuad(false), "normal-mapped.gltf");
        glb(normalMappedQuad(true), "normal-mapped-tangents.glb");
        glb(skinnedMorphedQuad(), "skinned-morphed.glb");
    } catch (const std::exception& error) {
        std::fprintf(stderr, "make_seeds: %s\n", error.what());
        return 1;
    }
    return 0;
}
