#pragma once
// What tinygltf 2.7.0 must be shown instead of a compressed file, because it refuses two
// things the compression extensions allow:
// - EXT_meshopt_compression's "fallback" buffer with no data at all (every view into it is
//   compressed; decoding fills it): in a .gltf tinygltf refuses a buffer without uri, in a
//   .glb it hands it the BIN chunk or fails when byteLength is larger. It is shown a 1-byte
//   data URI instead; GltfMeshoptDecoder gives every view into it bytes of its own and
//   refuses a view that would still read the placeholder.
// - KHR_draco_mesh_compression's index accessor without bufferView (its data is in the
//   Draco stream): tinygltf refuses a primitive's indices without a view. It is shown the
//   primitive's Draco bufferView; GltfDracoDecoder replaces the accessor's view anyway.
// Our own parse of the document stays as the file wrote it.
#include "GltfContainer.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <vector>

namespace engine::gltf {

// A buffer marked "extensions": {"EXT_meshopt_compression": {"fallback": true}} without uri.
bool isDatalessFallbackBuffer(const nlohmann::json& buffer);

// The file tinygltf should parse instead of the original (a .gltf's JSON text or a whole
// .glb), or empty when the document needs no placeholder.
std::vector<std::uint8_t> withCompressionPlaceholders(const nlohmann::json& document, const GltfContainer& container);

} // namespace engine::gltf
