#pragma once
// Test support for the glTF loader and mesh topology tests: a builder that writes glTF
// documents (JSON + one binary buffer) as .gltf (external .bin or data URI) or .glb into a
// temporary folder, so every bad case is spelled out in the test that uses it; and a cube
// with split vertices, as exporters write them.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <unistd.h>
#include <vector>

namespace gltf_test {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

// A fresh folder for one test's files, removed afterwards.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        path_ = fs::path(::testing::TempDir()) /
                ("engine_gltf_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

inline void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    ASSERT_TRUE(out.good()) << path;
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

// A glTF document under construction and its one binary buffer. Tests edit `doc` directly
// to make a file bad in exactly one way.
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
        doc["accessors"].push_back(accessor);
        return static_cast<int>(doc["accessors"].size() - 1);
    }
    int addFloats(const std::vector<float>& values, std::size_t components, const char* type) {
        return addAccessor(addView(values.data(), values.size() * sizeof(float)), kFloat, values.size() / components, type);
    }
    template <typename Index>
    int addIndices(const std::vector<Index>& indices) {
        const int componentType = sizeof(Index) == 1 ? kUnsignedByte : sizeof(Index) == 2 ? kUnsignedShort : kUnsignedInt;
        return addAccessor(addView(indices.data(), indices.size() * sizeof(Index)), componentType, indices.size(), "SCALAR");
    }
    int addMesh(const json& primitive) {
        doc["meshes"].push_back({{"primitives", json::array({primitive})}});
        return static_cast<int>(doc["meshes"].size() - 1);
    }
    int addNode(const json& node) {
        doc["nodes"].push_back(node);
        return static_cast<int>(doc["nodes"].size() - 1);
    }
    void setScene(const std::vector<int>& roots) {
        doc["scenes"] = json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }

    // name.gltf in `dir`, its buffer in name.bin or inline. A test that set "buffers"
    // itself keeps its own (the .bin file is still written).
    fs::path writeGltf(const fs::path& dir, const std::string& name,
                       BufferStorage storage = BufferStorage::ExternalFile) const {
        json out = doc;
        if (!bin.empty()) {
            writeBytes(dir / (name + ".bin"), bin);
            if (!out.contains("buffers")) {
                const std::string uri = storage == BufferStorage::ExternalFile
                                            ? name + ".bin"
                                            : "data:application/octet-stream;base64," + base64(bin);
                out["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", uri}}});
            }
        }
        const fs::path path = dir / (name + ".gltf");
        writeText(path, out.dump(1));
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

// A unit quad in the z = 0 plane, counter-clockwise seen from +z, as two indexed
// triangles, on one node of one scene. Tests break it in one place.
inline GltfBuilder quadScene() {
    GltfBuilder b;
    const int positions = b.addFloats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, 3, "VEC3");
    const int indices = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    b.addMesh({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
    b.addNode({{"name", "Quad"}, {"mesh", 0}});
    b.setScene({0});
    return b;
}

// Positions and triangle indices of an axis-aligned cube with 24 vertices: each face has
// its own four (as exporters split them along hard edges), wound counter-clockwise seen
// from outside.
struct CubeGeometry {
    std::vector<float> positions;  // x, y, z per vertex
    std::vector<std::uint32_t> indices;
};
inline CubeGeometry splitVertexCube(float cx = 0, float cy = 0, float cz = 0, float half = 1) {
    // Per face: outward normal n and in-plane axes u, v with u x v = n.
    const int faces[6][3][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
    };
    const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    const float center[3] = {cx, cy, cz};
    CubeGeometry cube;
    for (const auto& face : faces) {
        const auto first = static_cast<std::uint32_t>(cube.positions.size() / 3);
        for (const auto& corner : corners)
            for (int axis = 0; axis < 3; ++axis)
                cube.positions.push_back(center[axis] +
                                         half * (face[0][axis] + corner[0] * face[1][axis] + corner[1] * face[2][axis]));
        cube.indices.insert(cube.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    return cube;
}

// Loads `file` expecting an InputError whose message contains every one of `parts`.
inline void expectLoadError(const fs::path& file, std::initializer_list<std::string> parts,
                            const engine::GltfLoadOptions& options = {}) {
    try {
        engine::loadGltf(file, nullptr, options);
        ADD_FAILURE() << "loading " << file << " succeeded, expected an InputError";
    } catch (const engine::InputError& error) {
        const std::string message = error.what();
        for (const std::string& part : parts)
            EXPECT_NE(message.find(part), std::string::npos) << "message lacks '" << part << "': " << message;
    }
}

} // namespace gltf_test
