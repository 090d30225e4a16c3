#pragma once
// Runs tinygltf 2.7.0 with our guards: sandboxed file callbacks, an image "loader" that
// only keeps the encoded bytes (decoding happens later, after validation, in GltfImages),
// every call inside try/catch, and a non-empty error string treated as failure.
#include "GltfContainer.h"
#include "GltfContext.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <span>
#include <vector>

namespace engine::gltf {

struct ParsedGltf {
    tinygltf::Model model;
    // Encoded bytes of each image that came from a URI (file or data), by image index.
    // Empty for images stored in a bufferView: those are read after the view is validated.
    std::vector<std::vector<std::uint8_t>> uriImageBytes;
};

ParsedGltf parseWithTinygltf(const LoadContext& context, const GltfContainer& container,
                             std::span<const std::uint8_t> fileBytes);

} // namespace engine::gltf
