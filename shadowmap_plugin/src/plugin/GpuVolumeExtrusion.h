#pragma once
// Shadow volumes extruded in a geometry shader (the plugin's volume_extrusion "gpu"): for the
// closed meshes, the same classic volume ShadowVolumeMesh makes on the CPU, from each mesh's
// welded vertices and triangle adjacency uploaded once per scene (shaders/volume/
// shadow_volume.geom). The CPU then makes no triangle for those casters and uploads none per
// frame; open meshes and skinned or morphed casters stay on the CPU.
#include "math/ShadowVolumeMesh.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/VertexArray.h"
#include "engine/scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace shadowmap {

class GpuVolumeExtrusion {
public:
    GpuVolumeExtrusion();

    // Per Scene::meshes: the adjacency of the ones with a classic volume.
    void prepareScene(const std::vector<ShadowVolumeMesh>& meshes);
    bool extrudes(int mesh) const;

    // Within the volume pass's stencil state: draws `instance`'s volume from the light at
    // `lightWorld` ((position, 1) or (toward the light, 0), world space) through
    // viewProjection = P * V^-1. Returns the triangles it fed the geometry stage.
    std::uint64_t draw(const engine::MeshInstance& instance, const glm::dmat4& viewProjection,
                       const glm::dvec4& lightWorld) const;

private:
    struct Mesh {
        engine::gl::Buffer positions, indices;
        engine::gl::VertexArray array;
        std::uint64_t triangles = 0;
        glm::dvec3 center{0.0};  // the positions are relative to it, so they stay small in float
    };
    std::vector<Mesh> meshes_;
    engine::gl::Program program_;
};

} // namespace shadowmap
