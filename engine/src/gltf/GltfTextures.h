#pragma once
// glTF textures as a material references them: the file's samplers (enumerants checked) and
// a textureInfo (index, texCoord, KHR_texture_transform) turned into a TextureRef.
#include "GltfJsonFields.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <vector>

namespace engine::gltf {

// Every sampler of the document; a filter or wrap the file leaves out (or writes as -1,
// tinygltf's "undefined") keeps Sampler's default.
std::vector<Sampler> convertSamplers(const LoadContext& context, const nlohmann::json& document);

// The TextureRef of the textureInfo `info` (tinygltf's, indices validated) whose JSON is
// `fields`. Texture coordinate sets above 1 are not drawn: a warning, and set 0 instead.
TextureRef convertTextureRef(const tinygltf::Model& model, const std::vector<Sampler>& samplers,
                             const tinygltf::TextureInfo& info, const JsonFields& fields);

} // namespace engine::gltf
