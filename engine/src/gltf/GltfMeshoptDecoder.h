#pragma once
// EXT_meshopt_compression: each compressed bufferView is decoded (libmeshoptimizer) into a
// buffer of its own and the view is pointed at it, so validation and the converters see an
// ordinary file. Runs before validateModel; it checks everything it reads itself (the
// extension's buffer range, count, byteStride, mode and filter) and the decoded size
// against the view's byteLength. Index values are checked later, like any file's.
#include "GltfContext.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace engine::gltf {

// `document` is our own parse (the extension objects, and which buffers are dataless
// fallbacks); `model` is tinygltf's, whose buffers and bufferViews are rewritten.
void decodeMeshoptBufferViews(const LoadContext& context, const nlohmann::json& document, tinygltf::Model& model);

} // namespace engine::gltf
