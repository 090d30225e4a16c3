#pragma once
// Test support for the glTF loader and mesh topology tests: the glTF writer (gltf_writer.h,
// shared with the fuzzer's seeds), temporary folders for the files it writes, so every bad
// case is spelled out in the test that uses it; and a cube with split vertices, as exporters
// write them.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include "gltf_writer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace gltf_test {

using namespace gltf_writer;

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

// A 2x1 RGBA PNG: pixel 0 opaque red, pixel 1 blue with alpha 128. Its IHDR width is at
// byte 16, its zlib data at byte 41 (bad-input tests break it there).
inline const std::vector<std::uint8_t>& tinyPng() {
    static const std::vector<std::uint8_t> png = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
        0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4, 0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00,
        0x0e, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x42, 0x0d, 0x00, 0x0f, 0x7a, 0x03,
        0x7e, 0x77, 0xe9, 0x7f, 0x97, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    return png;
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
inline void expectLoadError(const fs::path& file, const std::vector<std::string>& parts,
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
