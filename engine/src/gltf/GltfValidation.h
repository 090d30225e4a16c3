#pragma once
// Structural validation tinygltf 2.7.0 leaves to us (it parses but never checks views, accessors, strides, counts, indices or cycles).
// Once validateModel() returns, the converters may follow every index and read every
// accessor's bytes without further range checks; what they still check are values
// (finite numbers, index values, types fitting their use).
#include "GltfContext.h"

#include <tiny_gltf.h>

namespace engine::gltf {

// Bytes per component for the glTF 2.0 component types, 0 for anything else.
std::size_t componentSize(int componentType);
// Components per element for SCALAR..MAT4, 0 for anything else.
std::size_t componentsPerElement(int type);

// Why a bufferView's byteStride is invalid (0 = absent is fine), or "".
std::string byteStrideProblem(std::uint64_t byteStride);

// Everything below, in an order where each check may rely on the ones before.
void validateModel(const LoadContext& context, const tinygltf::Model& model, std::size_t lightCount);

// Every view inside its buffer (64-bit, overflow-checked), strides in range.
void validateBufferViews(const LoadContext& context, const tinygltf::Model& model);
// Buffers, views and accessors: every byte an accessor may read lies inside its view and
// every view inside its buffer (64-bit, overflow-checked); strides and counts in range.
void validateBinaryLayout(const LoadContext& context, const tinygltf::Model& model);
// Indices between objects: meshes, materials, textures, images, nodes, scenes.
void validateReferences(const LoadContext& context, const tinygltf::Model& model, std::size_t lightCount);
// The node hierarchy is a forest (no cycles, one parent each, roots are roots) and every
// node transform is well formed.
void validateNodeGraph(const LoadContext& context, const tinygltf::Model& model);

} // namespace engine::gltf
