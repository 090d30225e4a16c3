#pragma once
// glTF 2.0 loading (.gltf with external or data-URI buffers, and .glb) into engine::Scene,
// through tinygltf 2.7.0, guarded against the crashes and escapes that version still has: our own
// file callbacks (scene folder only), our own image decoding, structural validation.
#include "engine/scene/Scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace engine {

struct GltfLoadOptions {
    // Limits that keep hostile files from causing giant allocations.
    std::uint64_t maxFileBytes = 1ull << 30;        // any single buffer/image file
    std::uint64_t maxElementCount = 1ull << 27;     // accessor count
    int maxImageDimension = 8192;
    int maxJsonDepth = 64;
};

// Loads the default glTF scene (or scene 0). Throws InputError("file: object: reason") on
// any bad input; appends non-fatal notes (dropped points/lines, generated normals...) to
// `warnings` when given.
Scene loadGltf(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr,
               const GltfLoadOptions& options = {});

} // namespace engine
