#pragma once
// The scene's casters' simplified levels (math/CasterLod.h) on the GPU, for caster_lod: per
// mesh that some instance casts with, its levels' errors, and per drawn primitive one index
// buffer holding every level's triangles one after another, uploaded once per scene. Drawn
// with the primitive's own vertex arrays (engine::SceneGpu::drawIndices), so a skinned or
// morphed instance's pose and an alpha-masked caster's UVs are the ones every level uses.
#include "engine/gl/Buffer.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <vector>

namespace shadowmap {

class CasterLods {
public:
    // Simplifies every caster mesh of `scene` (the meshes no instance casts with are left
    // alone) and uploads the levels. Needs a GL context.
    explicit CasterLods(const engine::Scene& scene);

    // The errors of the mesh's levels 1.. (object units, ascending); empty: it has none (or
    // it is not a mesh these levels were made for: one an edit added since).
    const std::vector<double>& errors(int mesh) const {
        static const std::vector<double> none;
        return mesh >= 0 && static_cast<std::size_t>(mesh) < meshes_.size() ? meshes_[mesh].errors : none;
    }

    // Draws `level` (0: as loaded) of the mesh's drawn primitive `primitive` (its index in
    // SceneGpu::primitives: the mesh's primitives that have triangles, in order) with that
    // primitive's vertex arrays; returns the triangles drawn.
    std::uint64_t draw(const engine::SceneGpu& gpu, const engine::SceneGpu::Primitive& drawn, int mesh,
                       std::size_t primitive, int level) const;

    // Per mesh with levels: its name, and the triangles and error of each level (0: as loaded).
    const nlohmann::json& stats() const { return stats_; }
    double buildSeconds() const { return buildSeconds_; }

private:
    struct Range {
        std::uint32_t first = 0, count = 0;
    };
    struct PrimitiveLevels {
        engine::gl::Buffer indices;  // levels 1.. one after another
        std::vector<Range> ranges;   // per level 1..
    };
    struct MeshLevels {
        std::vector<double> errors;
        std::vector<std::size_t> triangles;  // per level 1..
        std::vector<PrimitiveLevels> primitives;  // per drawn primitive
    };
    std::vector<MeshLevels> meshes_;
    double buildSeconds_ = 0.0;
    nlohmann::json stats_ = nlohmann::json::array();
};

} // namespace shadowmap
