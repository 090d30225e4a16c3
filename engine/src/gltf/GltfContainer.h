#pragma once
// The two containers of glTF: a .gltf file is JSON text; a .glb file is a 12-byte header
// and chunks (JSON, then optionally BIN). tinygltf 2.7.0's own GLB checks miss the BIN
// chunk's 8-byte header (a lying length reads past the file), so the layout is checked
// here, with messages that say which length is wrong, before tinygltf sees the bytes.
#include "GltfContext.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace engine::gltf {

struct GltfContainer {
    bool binary = false;
    std::string_view json;               // the glTF JSON text (views the file's bytes)
    std::span<const std::uint8_t> bin;   // GLB BIN chunk payload; empty when absent
};

bool hasGlbMagic(std::span<const std::uint8_t> fileBytes);

// Splits a GLB file into its chunks after checking magic, version 2, the header length
// against the file size, and every chunk length against what is left of the file.
GltfContainer splitGlb(const LoadContext& context, std::span<const std::uint8_t> fileBytes);

// The GLB file of `json` and `bin` (BIN chunk left out when empty), each chunk padded as
// the spec asks: JSON with spaces, BIN with zeros.
std::vector<std::uint8_t> joinGlb(std::string_view json, std::span<const std::uint8_t> bin);

// A .gltf file: all of it is JSON text.
GltfContainer wholeFileAsJson(std::span<const std::uint8_t> fileBytes);

} // namespace engine::gltf
