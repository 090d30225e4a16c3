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

// The TextureRef of a textureInfo whose JSON is `fields` and whose texture is
// `textureIndex` (tinygltf's `index`, validated; -1 when the material has no such texture).
// The index alone is taken from tinygltf because its TextureInfo, NormalTextureInfo and
// OcclusionTextureInfo are unrelated types that share nothing else; texCoord and
// KHR_texture_transform come from `fields`, so one function serves every material texture.
// Texture coordinate sets above 1 are not drawn: a warning, and set 0 instead.
TextureRef convertTextureRef(const tinygltf::Model& model, const std::vector<Sampler>& samplers, int textureIndex,
                             const JsonFields& fields);

} // namespace engine::gltf
