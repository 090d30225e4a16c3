#pragma once
// glTF meshes to engine meshes: triangle lists only (strips and fans converted, points and
// lines dropped with a warning), normals generated when absent, closedness computed.
#include "GltfContext.h"
#include "engine/scene/Scene.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace engine::gltf {

// The triangle list that draws `indices` in glTF primitive `mode` (TRIANGLES, or
// TRIANGLE_STRIP / TRIANGLE_FAN with the winding the glTF spec defines for each).
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& indices);

std::vector<Mesh> convertMeshes(const LoadContext& context, const tinygltf::Model& model);

} // namespace engine::gltf
