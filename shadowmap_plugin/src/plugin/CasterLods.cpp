#include "plugin/CasterLods.h"

#include "math/CasterLod.h"

#include <chrono>

namespace shadowmap {

CasterLods::CasterLods(const engine::Scene& scene) : meshes_(scene.meshes.size()) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<bool> casts(scene.meshes.size(), false);
    for (const engine::MeshInstance& instance : scene.meshInstances)
        if (instance.castShadows && instance.mesh >= 0) casts[instance.mesh] = true;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        if (!casts[m]) continue;
        const engine::Mesh& mesh = scene.meshes[m];
        // Alpha-masked casters' depth passes read their UVs: keep their seams.
        std::vector<bool> readsTexcoords;
        for (const engine::Primitive& primitive : mesh.primitives)
            readsTexcoords.push_back(primitive.material >= 0 &&
                                     engine::castsAlphaTested(scene.materials.at(primitive.material)));
        const std::vector<CasterLevel> levels = simplifiedLevels(mesh, readsTexcoords);
        if (levels.empty()) continue;
        MeshLevels& gpu = meshes_[m];
        nlohmann::json triangles = {mesh.triangleCount()}, errors = {0.0};
        for (const CasterLevel& level : levels) {
            gpu.errors.push_back(level.error);
            gpu.triangles.push_back(level.triangles);
            triangles.push_back(level.triangles);
            errors.push_back(level.error);
        }
        stats_.push_back({{"mesh", mesh.name}, {"closed", mesh.closed}, {"triangles", triangles}, {"error", errors}});
        // As SceneGpu lists them: the primitives that have triangles.
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            if (mesh.primitives[p].indices.empty()) continue;
            PrimitiveLevels& primitive = gpu.primitives.emplace_back();
            std::vector<std::uint32_t> all;
            for (const CasterLevel& level : levels) {
                const std::vector<std::uint32_t>& indices = level.indices[p];
                primitive.ranges.push_back({static_cast<std::uint32_t>(all.size()),
                                            static_cast<std::uint32_t>(indices.size())});
                all.insert(all.end(), indices.begin(), indices.end());
            }
            if (all.empty()) all.push_back(0);  // a buffer of no bytes cannot be created
            primitive.indices = engine::gl::Buffer::create(all.size() * sizeof(std::uint32_t), all.data());
        }
    }
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::uint64_t CasterLods::draw(const engine::SceneGpu& gpu, const engine::SceneGpu::Primitive& drawn, int mesh,
                               std::size_t primitive, int level) const {
    if (level <= 0) return gpu.draw(drawn);
    const PrimitiveLevels& levels = meshes_.at(mesh).primitives.at(primitive);
    const Range& range = levels.ranges.at(level - 1);
    return gpu.drawIndices(drawn, levels.indices, range.first, range.count);
}

} // namespace shadowmap
