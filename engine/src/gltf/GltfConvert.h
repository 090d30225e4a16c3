#pragma once
// tinygltf's model (validated) to engine::Scene. Each converter checks the values it
// converts (finite, in range, known enumerants); indices were checked by GltfValidation.
#include "GltfParse.h"

#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

namespace engine::gltf {

// `document` is our own parse of the JSON: extensions and extras are read from it exactly
// as written (GltfJsonFields.h says why).
std::vector<Material> convertMaterials(const LoadContext& context, const tinygltf::Model& model,
                                       const nlohmann::json& document);
std::vector<Camera> convertCameras(const LoadContext& context, const tinygltf::Model& model);

// The whole scene: nodes (transforms, light references, shadow extras), the displayed
// scene's roots, meshes, materials, images, cameras and the given lights; world transforms
// and instances already computed.
Scene convertToScene(const LoadContext& context, const ParsedGltf& parsed, const nlohmann::json& document,
                     std::vector<Light> lights);

} // namespace engine::gltf
