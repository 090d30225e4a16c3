#pragma once
// KHR_draco_mesh_compression: each compressed primitive is decoded (libdraco) and its
// accessors are given plain data (FLOAT attributes, UNSIGNED_INT indices) in buffers of their
// own, so validation and the converters see an ordinary file. Runs after validateBufferViews
// (it reads a view's bytes) and before validateModel (a Draco accessor has no bufferView
// until then). Every count and index the decoder returns is checked before use.
#include "GltfContext.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace engine::gltf {

// `document` is our own parse (the extension objects); `model` is tinygltf's, whose
// buffers, bufferViews, accessors and primitives are rewritten.
void decodeDracoPrimitives(const LoadContext& context, const nlohmann::json& document, tinygltf::Model& model);

} // namespace engine::gltf
