#pragma once
// tinygltf's model (validated) to engine::Scene. Each converter checks the values it
// converts (finite, in range, known enumerants); indices were checked by GltfValidation.
#include "GltfParse.h"

#include "engine/scene/Scene.h"

namespace engine::gltf {

std::vector<Material> convertMaterials(const LoadContext& context, const tinygltf::Model& model);
std::vector<Camera> convertCameras(const LoadContext& context, const tinygltf::Model& model);

// The whole scene: nodes (transforms, light references, shadow extras), the displayed
// scene's roots, meshes, materials, images, cameras and the given lights; world transforms
// and instances already computed.
Scene convertToScene(const LoadContext& context, const ParsedGltf& parsed, std::vector<Light> lights);

} // namespace engine::gltf
