#pragma once
// Checks on the raw JSON document that must happen before tinygltf runs, because tinygltf
// acts on what it reads: it opens every URI, decodes every data URI, copies GLB buffers,
// and ignores `extensionsRequired`.
#include "GltfContainer.h"
#include "GltfContext.h"

#include <nlohmann/json.hpp>

namespace engine::gltf {

// The extensions this loader implements; a file that requires any other is refused.
bool isSupportedExtension(const std::string& name);

// asset.version 2.x; extensionsRequired; the JSON types of the properties we consume;
// every buffer (byteLength, where its bytes come
// from, URI inside the scene's folder, data URI size), every image URI, and the
// bufferView strides tinygltf would refuse without naming the view.
void preflightDocument(const LoadContext& context, const nlohmann::json& document,
                       const GltfContainer& container);

} // namespace engine::gltf
