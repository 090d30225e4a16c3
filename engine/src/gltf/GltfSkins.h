#pragma once
// glTF skins, and what nodes bring to a deformed mesh: their skin and morph weights.
#include "GltfContext.h"
#include "engine/scene/Scene.h"

#include <tiny_gltf.h>

#include <vector>

namespace engine::gltf {

// Every skin: at least one joint, each a node at most once; inverseBindMatrices a MAT4 FLOAT
// accessor with one finite matrix per joint (identity for all when absent).
std::vector<Skin> readSkins(const LoadContext& context, const tinygltf::Model& model);

// Sets node.skin and node.weights from the file, after checking them against the node's
// mesh: a skinned mesh's primitives all have JOINTS_0/WEIGHTS_0 (a skin on a mesh without
// them is ignored, with a warning), every joint index of every vertex names one of the
// skin's joints, and the node's weights give one finite value per morph target.
void attachDeformers(const LoadContext& context, const tinygltf::Model& model, const std::vector<Skin>& skins,
                     const std::vector<Mesh>& meshes, std::vector<Node>& nodes);

} // namespace engine::gltf
