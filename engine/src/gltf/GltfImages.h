#pragma once
// Image decoding, done by us after validation rather than by tinygltf during parsing:
// tinygltf 2.7.0 hands stb an unchecked bufferView range (out-of-bounds read), accepts any
// format stb knows whatever the mimeType, and has no size cap (decompression bombs).
#include "GltfParse.h"

#include "engine/scene/Scene.h"

namespace engine::gltf {

// Every image of the model as RGBA8: PNG or JPEG only (by magic), dimensions checked
// against options.maxImageDimension before any pixel is decoded.
std::vector<Image> decodeImages(const LoadContext& context, const ParsedGltf& parsed);

} // namespace engine::gltf
