#pragma once
// A small glTF writer: a document (JSON) and its one binary buffer, built up in code and
// written as .gltf (external .bin or data URI) or .glb. No test framework and no engine
// code, so that both the loader tests (through gltf_test_support.h) and the fuzzer's seed
// writer (tools/fuzz/make_seeds.cpp) build their files with it.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gltf_writer {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kByte = 5120;
constexpr int kUnsignedByte = 5121;
constexpr int kShort = 5122;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

// Throws std::runtime_error if the file cannot be written.
inline void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out.good()) throw std::runtime_error("cannot write " + path.string());
}
inline void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    writeBytes(path, bytes.data(), bytes.size());
}
inline void writeText(const fs::path& path, const std::string& text) { writeBytes(path, text.data(), text.size()); }

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
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

enum class BufferStorage { ExternalFile, DataUri };

// A glTF document under construction and its one binary buffer. Callers may edit `doc`
// directly (tests do, to make a file bad in exactly one way).
struct GltfBuilder {
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<std::uint8_t> bin;

    // Appends bytes (4-byte aligned) as a new bufferView; returns its index.
    int addView(const void* data, std::size_t size, std::size_t stride = 0) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (stride != 0) view["byteStride"] = stride;
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), bytes, bytes + size);
        doc["bufferViews"].push_back(view);
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }
    int addAccessor(int view, int componentType, std::size_t count, const char* type, bool normalized = false) {
        json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) accessor["normalized"] = true;
        return add("accessors", accessor);
    }
    int addFloats(const std::vector<float>& values, std::size_t components, const char* type) {
        return addAccessor(addView(values.data(), values.size() * sizeof(float)), kFloat, values.size() / components, type);
    }
    // POSITION data (x y z per vertex) with the min and max glTF requires on it.
    int addPositions(const std::vector<float>& xyz) {
        const int accessor = addFloats(xyz, 3, "VEC3");
        setBounds(accessor, xyz);
        return accessor;
    }
    // Per-component min and max of x y z values on a VEC3 accessor.
    void setBounds(int accessor, const std::vector<float>& xyz) {
        std::vector<float> low(xyz.begin(), xyz.begin() + 3), high = low;
        for (std::size_t i = 0; i < xyz.size(); ++i) {
            low[i % 3] = std::min(low[i % 3], xyz[i]);
            high[i % 3] = std::max(high[i % 3], xyz[i]);
        }
        doc["accessors"][accessor]["min"] = low;
        doc["accessors"][accessor]["max"] = high;
    }
    template <typename Index>
    int addIndices(const std::vector<Index>& indices) {
        const int componentType = sizeof(Index) == 1 ? kUnsignedByte : sizeof(Index) == 2 ? kUnsignedShort : kUnsignedInt;
        return addAccessor(addView(indices.data(), indices.size() * sizeof(Index)), componentType, indices.size(), "SCALAR");
    }
    int addMesh(const json& primitive) { return add("meshes", {{"primitives", json::array({primitive})}}); }
    int addNode(const json& node) { return add("nodes", node); }
    // Appends `value` to the top-level array `array` (images, materials...); returns its index.
    int add(const char* array, json value) {
        doc[array].push_back(std::move(value));
        return static_cast<int>(doc[array].size() - 1);
    }
    void setScene(const std::vector<int>& roots) {
        doc["scenes"] = json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }

    // The .gltf text (JSON, indented by 1). Unless the document sets "buffers" itself, the
    // buffer is the file `binUri` or inline as a data URI.
    std::string gltfText(BufferStorage storage, const std::string& binUri = {}) const {
        json out = doc;
        if (!bin.empty() && !out.contains("buffers")) {
            const std::string uri = storage == BufferStorage::ExternalFile
                                        ? binUri
                                        : "data:application/octet-stream;base64," + base64(bin);
            out["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", uri}}});
        }
        return out.dump(1);
    }

    // name.gltf in `dir`, its buffer in name.bin or inline. The .bin file is written either
    // way (a caller that set "buffers" itself may point at it).
    fs::path writeGltf(const fs::path& dir, const std::string& name,
                       BufferStorage storage = BufferStorage::ExternalFile) const {
        if (!bin.empty()) writeBytes(dir / (name + ".bin"), bin);
        const fs::path path = dir / (name + ".gltf");
        writeText(path, gltfText(storage, name + ".bin"));
        return path;
    }

    // The GLB bytes: header, JSON chunk (space padded), BIN chunk (zero padded).
    std::vector<std::uint8_t> glbBytes() const {
        json out = doc;
        if (!bin.empty() && !out.contains("buffers")) out["buffers"] = json::array({{{"byteLength", bin.size()}}});
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
        const std::uint32_t total = 12 + 8 + static_cast<std::uint32_t>(text.size()) +
                                    (payload.empty() ? 0 : 8 + static_cast<std::uint32_t>(payload.size()));
        u32(0x46546C67);  // "glTF"
        u32(2);
        u32(total);
        u32(static_cast<std::uint32_t>(text.size()));
        u32(0x4E4F534A);  // "JSON"
        glb.insert(glb.end(), text.begin(), text.end());
        if (!payload.empty()) {
            u32(static_cast<std::uint32_t>(payload.size()));
            u32(0x004E4942);  // "BIN\0"
            glb.insert(glb.end(), payload.begin(), payload.end());
        }
        return glb;
    }
    fs::path writeGlb(const fs::path& dir, const std::string& name) const {
        const fs::path path = dir / (name + ".glb");
        writeBytes(path, glbBytes());
        return path;
    }
};

// Appends an animation 'SlideTurnGrow' of `node`, one sampler per interpolation, all keyed
// at 0 and 1 s: samplers[0] LINEAR translation (0,0,0) -> (2,0,0); samplers[1] STEP rotation
// as normalized SHORT, identity then 90 degrees about +Z (0, 0, 23170, 23170) / 32767;
// samplers[2] CUBICSPLINE scale 1 -> 3 with flat tangents. channels[i] uses samplers[i].
// Returns the animation's index.
inline int addSlideTurnGrowAnimation(GltfBuilder& b, int node) {
    const int times = b.addFloats({0, 1}, 1, "SCALAR");
    b.doc["accessors"][times]["min"] = {0};  // glTF requires min and max on animation inputs
    b.doc["accessors"][times]["max"] = {1};
    const int slide = b.addFloats({0, 0, 0, 2, 0, 0}, 3, "VEC3");
    const std::vector<std::int16_t> turnKeys = {0, 0, 0, 32767, 0, 0, 23170, 23170};
    const int turn = b.addAccessor(b.addView(turnKeys.data(), turnKeys.size() * 2), kShort, 2, "VEC4", true);
    // (in-tangent, value, out-tangent) per key.
    const int grow = b.addFloats({0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 3, 3, 3, 0, 0, 0}, 3, "VEC3");
    const auto channel = [&](int sampler, const char* path) {
        return json{{"sampler", sampler}, {"target", {{"node", node}, {"path", path}}}};
    };
    return b.add("animations",
                 {{"name", "SlideTurnGrow"},
                  {"samplers",
                   {{{"input", times}, {"output", slide}},
                    {{"input", times}, {"output", turn}, {"interpolation", "STEP"}},
                    {{"input", times}, {"output", grow}, {"interpolation", "CUBICSPLINE"}}}},
                  {"channels", {channel(0, "translation"), channel(1, "rotation"), channel(2, "scale")}}});
}

// A unit quad in z = 0 (vertices (0,0), (1,0), (1,1), (0,1)) on node 0 'Skinned', whose own
// translation (100, 0, 0) a skinned mesh must ignore. Vertices 0, 1 follow joint 0 'Root'
// (node 1, at the origin); vertex 2 follows joint 1 'Tip' (node 2, child of Root at y = 1,
// bound there: inverse bind matrix T(0, -1, 0)); vertex 3 is half Root, half Tip.
inline GltfBuilder skinnedQuad() {
    GltfBuilder b;
    const int positions = b.addPositions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    const std::vector<std::uint8_t> joints = {0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};
    const int jointAccessor = b.addAccessor(b.addView(joints.data(), joints.size()), kUnsignedByte, 4, "VEC4");
    const int weights = b.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, 4, "VEC4");
    const int indices = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    b.addMesh({{"attributes", {{"POSITION", positions}, {"JOINTS_0", jointAccessor}, {"WEIGHTS_0", weights}}},
               {"indices", indices}});
    const int inverseBind = b.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,    // identity
                                         1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},  // T(0, -1, 0)
                                        16, "MAT4");
    b.add("skins", {{"joints", {1, 2}}, {"inverseBindMatrices", inverseBind}});
    b.addNode({{"name", "Skinned"}, {"mesh", 0}, {"skin", 0}, {"translation", {100, 0, 0}}});
    b.addNode({{"name", "Root"}, {"children", {2}}});
    b.addNode({{"name", "Tip"}, {"translation", {0, 1, 0}}});
    b.setScene({0, 1});
    return b;
}

} // namespace gltf_writer
