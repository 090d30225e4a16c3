#pragma once
// EXT_meshopt_compression lets a file declare a "fallback" buffer that has no data at all:
// every view into it is compressed, and decoding fills it. tinygltf 2.7.0 cannot read such a
// buffer (in a .gltf it refuses a buffer without uri; in a .glb it hands it the BIN chunk, or
// fails when byteLength is larger). So tinygltf is given the same document with each such
// buffer replaced by a 1-byte data URI; GltfMeshoptDecoder then gives every view into it
// bytes of its own and refuses a view that would still read the placeholder.
#include "GltfContainer.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <vector>

namespace engine::gltf {

// A buffer marked "extensions": {"EXT_meshopt_compression": {"fallback": true}} without uri.
bool isDatalessFallbackBuffer(const nlohmann::json& buffer);

// The file tinygltf should parse instead of the original (a .gltf's JSON text or a whole
// .glb), or empty when the document has no dataless fallback buffer.
std::vector<std::uint8_t> withPlaceholderFallbackBuffers(const nlohmann::json& document,
                                                         const GltfContainer& container);

} // namespace engine::gltf
