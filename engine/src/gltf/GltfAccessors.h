#pragma once
// One reader for every accessor: positions, normals, texture coordinates and indices all
// go through forEachElement, which walks a validated accessor's elements with its stride.
#include "GltfContext.h"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace engine::gltf {

// What a particular use of an accessor requires of it.
struct AccessorUse {
    enum class Components {
        Float,              // FLOAT only (positions, normals)
        FloatOrNormalized,  // FLOAT, or normalized UNSIGNED_BYTE/SHORT (colors)
        // KHR_mesh_quantization: FLOAT, or BYTE/SHORT normalized (normals, tangents and
        // their morph offsets)
        FloatOrSignedNormalized,
        // KHR_mesh_quantization: FLOAT, or any 8/16-bit integer, normalized or not
        // (positions, texture coordinates); the node transform dequantizes.
        Quantized,
        UnsignedInteger,    // UNSIGNED_BYTE/SHORT/INT, not normalized (indices)
        // FLOAT, or any normalized 8/16-bit integer (animated rotations and weights)
        FloatOrAnyNormalized,
    };
    std::string usedAs;  // "POSITION of meshes[0].primitives[1]", for messages
    int type = TINYGLTF_TYPE_SCALAR;
    Components components = Components::Float;
    int alternativeType = -1;  // a second type the use accepts (COLOR_0: VEC3 or VEC4), -1 none
};

// All components of the accessor (count x components per element), as float: normalized
// unsigned integers map to [0, 1], normalized signed ones to [-1, 1] (glTF: max(c / MAX, -1)),
// integers that are not normalized keep their value. Refuses an accessor whose type does not fit `use`, and any value
// that is not finite. With an alternativeType, the caller asks the accessor which it is. The accessor must have passed validateBinaryLayout.
std::vector<float> readFloatComponents(const LoadContext& context, const tinygltf::Model& model,
                                       int accessorIndex, const AccessorUse& use);

// All components of an accessor of unsigned integers (indices, JOINTS_0), count x
// components per element.
std::vector<std::uint32_t> readUnsignedIntegers(const LoadContext& context, const tinygltf::Model& model,
                                                int accessorIndex, const AccessorUse& use);

template <glm::length_t N>
std::vector<glm::vec<N, float>> readFloatVectors(const LoadContext& context, const tinygltf::Model& model,
                                                 int accessorIndex, const AccessorUse& use) {
    const std::vector<float> flat = readFloatComponents(context, model, accessorIndex, use);
    std::vector<glm::vec<N, float>> vectors(flat.size() / N);
    for (std::size_t i = 0; i < vectors.size(); ++i)
        for (glm::length_t c = 0; c < N; ++c) vectors[i][c] = flat[i * N + c];
    return vectors;
}

} // namespace engine::gltf
