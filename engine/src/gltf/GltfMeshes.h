#pragma once
// glTF meshes to engine meshes: triangle lists only (strips and fans converted, points and
// lines dropped with a warning), normals generated when absent, tangents read (TANGENT) or
// generated for normal-mapped materials (Tangents.h), closedness computed; two UV sets,
// vertex colors, skin weights, morph targets and KHR_lights_shadows per primitive.
#include "GltfContext.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace engine::gltf {

// The triangle list that draws `indices` in glTF primitive `mode` (TRIANGLES, or
// TRIANGLE_STRIP / TRIANGLE_FAN with the winding the glTF spec defines for each).
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& indices);

// glTF `weights` (of a mesh or a node) as floats: exactly `targets` finite values, else a
// failure naming `object` ("... entries for 2 <targetsName>").
std::vector<float> checkedMorphWeights(const LoadContext& context, const std::string& object,
                                       const std::vector<double>& weights, std::size_t targets, const char* targetsName);

// `document` is our own parse (primitive extensions); `materials` the converted materials:
// a primitive lacking the UV set its material's texture samples is reported, and one whose
// material has a normal texture gets tangents.
std::vector<Mesh> convertMeshes(const LoadContext& context, const tinygltf::Model& model,
                                const nlohmann::json& document, const std::vector<Material>& materials);

} // namespace engine::gltf
