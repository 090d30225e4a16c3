// Writes the fuzz seed corpus: make_seeds OUT_DIR SCENES_DIR
//   - every .gltf/.glb of SCENES_DIR (content/scenes: showcase.gltf; its showcase.bin is
//     next to the fuzzed file, gltf_fuzzer.cpp copies it there),
//   - small self-contained scenes that together reach every feature the loader converts:
//     data-URI and GLB buffers, interleaved views, 8/16/32-bit indices, strips and fans,
//     points and lines (dropped), normalized texcoords, PNG and JPEG images from a data URI,
//     a bufferView and a file URI ('tex.png', also next to the fuzzed file), materials,
//     both camera types, KHR_lights_punctual, node hierarchies with TRS and matrices.
// Small on purpose: libFuzzer mutates short inputs much faster.
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
        std::fprintf(stderr, "make_seeds: cannot write %s\n", path.c_str());
        std::exit(1);
    }
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (bytes[i] << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                                (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += alphabet[(n >> 18) & 63];
        out += alphabet[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
    }
    return out;
}

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

// A glTF document and its one binary buffer (as tests/unit/gltf_test_support.h builds them).
struct Builder {
    json doc = {{"asset", {{"version", "2.0"}, {"generator", "tools/fuzz/make_seeds"}}}};
    std::vector<std::uint8_t> bin;

    int addView(const void* data, std::size_t size, std::size_t stride = 0) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (stride != 0) view["byteStride"] = stride;
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), bytes, bytes + size);
        doc["bufferViews"].push_back(view);
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }
    int addAccessor(json accessor) {
        doc["accessors"].push_back(std::move(accessor));
        return static_cast<int>(doc["accessors"].size() - 1);
    }
    int addFloats(const std::vector<float>& values, std::size_t components, const char* type) {
        const int view = addView(values.data(), values.size() * sizeof(float));
        return addAccessor({{"bufferView", view}, {"componentType", kFloat},
                            {"count", values.size() / components}, {"type", type}});
    }
    template <typename Index>
    int addIndices(const std::vector<Index>& indices) {
        const int type = sizeof(Index) == 1 ? kUnsignedByte : sizeof(Index) == 2 ? kUnsignedShort : kUnsignedInt;
        const int view = addView(indices.data(), indices.size() * sizeof(Index));
        return addAccessor({{"bufferView", view}, {"componentType", type}, {"count", indices.size()}, {"type", "SCALAR"}});
    }
    int add(const char* array, json value) {
        doc[array].push_back(std::move(value));
        return static_cast<int>(doc[array].size() - 1);
    }

    void writeGltf(const fs::path& path) const {
        json out = doc;
        if (!bin.empty())
            out["buffers"] = json::array(
                {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        const std::string text = out.dump(1);
        writeBytes(path, text.data(), text.size());
    }
    void writeGlb(const fs::path& path) const {
        json out = doc;
        if (!bin.empty()) out["buffers"] = json::array({{{"byteLength", bin.size()}}});
        std::string text = out.dump();
        while (text.size() % 4 != 0) text += ' ';
        std::vector<std::uint8_t> payload = bin;
        while (payload.size() % 4 != 0) payload.push_back(0);
        std::vector<std::uint8_t> glb;
        const auto u32 = [&](std::uint32_t v) {
            const std::size_t at = glb.size();
            glb.resize(at + 4);
            std::memcpy(glb.data() + at, &v, 4);
        };
        u32(0x46546C67);  // "glTF"
        u32(2);
        u32(static_cast<std::uint32_t>(12 + 8 + text.size() + (payload.empty() ? 0 : 8 + payload.size())));
        u32(static_cast<std::uint32_t>(text.size()));
        u32(0x4E4F534A);  // "JSON"
        glb.insert(glb.end(), text.begin(), text.end());
        if (!payload.empty()) {
            u32(static_cast<std::uint32_t>(payload.size()));
            u32(0x004E4942);  // "BIN\0"
            glb.insert(glb.end(), payload.begin(), payload.end());
        }
        writeBytes(path, glb.data(), glb.size());
    }
};

const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

// One indexed triangle: the smallest scene that loads and draws.
Builder triangle() {
    Builder b;
    const int positions = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3, "VEC3");
    const int indices = b.addIndices(std::vector<std::uint8_t>{0, 1, 2});
    b.add("meshes", {{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}});
    b.add("nodes", {{"mesh", 0}});
    b.doc["scenes"] = json::array({{{"nodes", {0}}}});
    b.doc["scene"] = 0;
    return b;
}

// A textured quad: NORMAL, normalized TEXCOORD_0, material, image in a bufferView (PNG or
// JPEG), a perspective camera on a TRS node.
Builder texturedQuad(bool jpeg) {
    Builder b;
    const int positions = b.addFloats(kQuadPositions, 3, "VEC3");
    const int normals = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, 3, "VEC3");
    const std::vector<std::uint8_t> uv = {0, 255, 255, 255, 255, 0, 0, 0};
    const int uvView = b.addView(uv.data(), uv.size());
    const int texcoords = b.addAccessor({{"bufferView", uvView}, {"componentType", kUnsignedByte},
                                         {"normalized", true}, {"count", 4}, {"type", "VEC2"}});
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
Builder lightsAndHierarchy() {
    Builder b;
    const int positions = b.addFloats(kQuadPositions, 3, "VEC3");
    const int indices = b.addIndices(std::vector<std::uint32_t>{0, 1, 2, 2, 3, 0});
    b.add("images", {{"uri", "tex.png"}, {"name", "file"}});
    b.add("images", {{"uri", "data:image/png;base64," + base64(encodeImage(false))}});
    b.add("textures", {{"source", 0}});
    b.add("textures", {{"source", 1}});
    b.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}, {"alphaMode", "BLEND"}});
    b.add("meshes", {{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices},
                                      {"material", 0}}}}});
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
Builder primitiveModes() {
    Builder b;
    // x y z nx ny nz per vertex, interleaved.
    const std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1,
                                            1, 1, 0, 0, 0, 1, 0, 2, 0, 0, 0, 1};
    const int view = b.addView(interleaved.data(), interleaved.size() * sizeof(float), 24);
    const int positions = b.addAccessor({{"bufferView", view}, {"componentType", kFloat}, {"count", 5}, {"type", "VEC3"}});
    const int normals = b.addAccessor({{"bufferView", view}, {"byteOffset", 12}, {"componentType", kFloat},
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

// An accessor without a bufferView (all zeros, glTF 2.0), alone so that the other seeds
// still load if the loader refuses these.
Builder zeroAccessor() {
    Builder b = triangle();
    b.doc["accessors"][0].erase("bufferView");
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

    const std::string minimal = R"({"asset":{"version":"2.0"}})";
    writeBytes(out / "minimal.gltf", minimal.data(), minimal.size());
    triangle().writeGltf(out / "triangle.gltf");
    triangle().writeGlb(out / "triangle.glb");
    texturedQuad(false).writeGlb(out / "quad-png.glb");
    texturedQuad(true).writeGlb(out / "quad-jpeg.glb");
    texturedQuad(false).writeGltf(out / "quad-png.gltf");
    lightsAndHierarchy().writeGltf(out / "lights.gltf");
    lightsAndHierarchy().writeGlb(out / "lights.glb");
    primitiveModes().writeGlb(out / "modes.glb");
    primitiveModes().writeGltf(out / "modes.gltf");
    zeroAccessor().writeGltf(out / "zeros.gltf");
    return 0;
}
