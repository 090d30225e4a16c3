#include "plugin/GpuVolumeExtrusion.h"

#include <glm/gtc/matrix_transform.hpp>

#include <epoxy/gl.h>

#include <cstdio>
#include <string>

namespace shadowmap {

namespace shaders {
extern const char shadow_volume_gpu_vert[];
extern const char shadow_volume_geom[];
extern const char shadow_volume_frag[];
} // namespace shaders

namespace {

engine::gl::Program compileProgram() {
    char edgeOn[64];
    std::snprintf(edgeOn, sizeof edgeOn, "#define EDGE_ON_SINE %.9g\n", kEdgeOnSine);
    const std::string header = "#version 450 core\n";
    return engine::gl::Program::compile("shadow volumes (geometry shader)",
                                        {{GL_VERTEX_SHADER, header + shaders::shadow_volume_gpu_vert},
                                         {GL_GEOMETRY_SHADER, header + edgeOn + shaders::shadow_volume_geom},
                                         {GL_FRAGMENT_SHADER, header + shaders::shadow_volume_frag}});
}

} // namespace

GpuVolumeExtrusion::GpuVolumeExtrusion() : program_(compileProgram()) {}

void GpuVolumeExtrusion::prepareScene(const std::vector<ShadowVolumeMesh>& meshes) {
    meshes_.clear();
    meshes_.resize(meshes.size());
    for (std::size_t index = 0; index < meshes.size(); ++index) {
        const std::vector<std::uint32_t> adjacency = meshes[index].adjacencyIndices();
        if (adjacency.empty()) continue;
        const std::vector<glm::dvec3>& welded = meshes[index].weldedPositions();
        Mesh& mesh = meshes_[index];
        glm::dvec3 low = welded.front(), high = welded.front();
        for (const glm::dvec3& p : welded) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        mesh.center = (low + high) * 0.5;
        std::vector<glm::vec3> positions;
        positions.reserve(welded.size());
        for (const glm::dvec3& p : welded) positions.emplace_back(p - mesh.center);
        mesh.positions = engine::gl::Buffer::create(positions.size() * sizeof(glm::vec3), positions.data());
        mesh.indices = engine::gl::Buffer::create(adjacency.size() * sizeof(std::uint32_t), adjacency.data());
        mesh.array = engine::gl::VertexArray::create();
        mesh.array.attribute(0, mesh.positions, 3, GL_FLOAT, sizeof(glm::vec3), 0);
        mesh.array.elementBuffer(mesh.indices);
        mesh.triangles = adjacency.size() / 6;
    }
}

bool GpuVolumeExtrusion::extrudes(int mesh) const {
    return mesh >= 0 && static_cast<std::size_t>(mesh) < meshes_.size() && meshes_[mesh].triangles > 0;
}

std::uint64_t GpuVolumeExtrusion::draw(const engine::MeshInstance& instance, const glm::dmat4& viewProjection,
                                       const glm::dvec4& lightWorld) const {
    const Mesh& mesh = meshes_[instance.mesh];
    const glm::dmat4 model = glm::translate(instance.world, mesh.center);
    program_.use();
    // Composed in double: V^-1 * M is camera-relative, so its float product stays small.
    program_.set("uModelViewProjection", glm::mat4(viewProjection * model));
    program_.set("uLight", glm::vec4(glm::inverse(model) * lightWorld));
    mesh.array.bind();
    glDrawElements(GL_TRIANGLES_ADJACENCY, static_cast<GLsizei>(6 * mesh.triangles), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    return mesh.triangles;
}

} // namespace shadowmap
