#include "math/CasterLod.h"

#include "math/SurfaceDistance.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <map>
#include <unordered_map>
#include <cmath>

namespace shadowmap {

namespace {

std::vector<SurfaceTriangle> trianglesOf(const engine::Mesh& mesh,
                                         const std::vector<std::vector<std::uint32_t>>* levelIndices) {
    std::vector<SurfaceTriangle> triangles;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const engine::Primitive& primitive = mesh.primitives[p];
        const std::vector<std::uint32_t>& indices = levelIndices ? (*levelIndices)[p] : primitive.indices;
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
            triangles.push_back({glm::dvec3(primitive.positions[indices[i]]), glm::dvec3(primitive.positions[indices[i + 1]]),
                                 glm::dvec3(primitive.positions[indices[i + 2]])});
    }
    return triangles;
}

// The primitive's triangles with every vertex replaced by the first one that deforms alike:
// the same position, and the same joints, weights and morph offsets where it has them.
// The depth pass reads nothing else of an opaque caster, and its seams (normals, UVs) are
// gone, so the simplifier may collapse across them and a closed mesh stays closed.
std::vector<std::uint32_t> depthOnlyIndices(const engine::Primitive& primitive) {
    const std::size_t count = primitive.positions.size();
    std::vector<meshopt_Stream> streams{{primitive.positions.data(), sizeof(glm::vec3), sizeof(glm::vec3)}};
    if (primitive.joints.size() == count && primitive.weights.size() == count) {
        streams.push_back({primitive.joints.data(), sizeof(glm::uvec4), sizeof(glm::uvec4)});
        streams.push_back({primitive.weights.data(), sizeof(glm::vec4), sizeof(glm::vec4)});
    }
    for (const engine::MorphTarget& target : primitive.targets)
        if (target.positions.size() == count)
            streams.push_back({target.positions.data(), sizeof(glm::vec3), sizeof(glm::vec3)});
    std::vector<std::uint32_t> welded(primitive.indices.size());
    meshopt_generateShadowIndexBufferMulti(welded.data(), primitive.indices.data(), primitive.indices.size(), count,
                                           streams.data(), streams.size());
    return welded;
}

// One level: each primitive simplified from its triangles as loaded toward `fraction` of
// them. Returns the simplifier's largest error estimate in object units.
double simplify(const engine::Mesh& mesh, const std::vector<std::vector<std::uint32_t>>& sources, double fraction,
                const CasterLodOptions& options, CasterLevel& level) {
    double estimate = 0.0;
    level.indices.resize(mesh.primitives.size());
    level.triangles = 0;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const engine::Primitive& primitive = mesh.primitives[p];
        std::vector<std::uint32_t>& out = level.indices[p];
        if (primitive.indices.size() < 3) continue;
        const float* positions = &primitive.positions[0].x;
        const std::size_t target =
            3 * static_cast<std::size_t>(std::ceil(static_cast<double>(primitive.triangleCount()) * fraction));
        out.resize(primitive.indices.size());
        float relative = 0.0f;
        out.resize(meshopt_simplify(out.data(), sources[p].data(), sources[p].size(), positions,
                                    primitive.positions.size(), sizeof(glm::vec3), target,
                                    static_cast<float>(options.maxRelativeError), meshopt_SimplifyLockBorder, &relative));
        const double scale = meshopt_simplifyScale(positions, primitive.positions.size(), sizeof(glm::vec3));
        estimate = std::max(estimate, static_cast<double>(relative) * scale);
        level.triangles += out.size() / 3;
    }
    return estimate;
}

} // namespace

std::vector<SurfaceTriangle> meshTriangles(const engine::Mesh& mesh) { return trianglesOf(mesh, nullptr); }

std::vector<SurfaceTriangle> levelTriangles(const engine::Mesh& mesh, const CasterLevel& level) {
    return trianglesOf(mesh, &level.indices);
}

bool levelIsClosed(const engine::Mesh& mesh, const CasterLevel& level) {
    std::map<std::array<float, 3>, std::uint32_t> welded;  // by exact position
    // Per undirected edge (a < b): times walked a -> b minus times walked b -> a.
    std::unordered_map<std::uint64_t, std::int64_t> balance;
    std::size_t used = 0;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::vector<glm::vec3>& positions = mesh.primitives[p].positions;
        const std::vector<std::uint32_t>& indices = level.indices[p];
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            std::uint32_t corner[3];
            for (int c = 0; c < 3; ++c) {
                // +0.0f and -0.0f are one position (as isClosedSurface welds them).
                const glm::vec3 q = positions[indices[t + c]] + glm::vec3(0.0f);
                corner[c] = welded.emplace(std::array<float, 3>{q.x, q.y, q.z}, static_cast<std::uint32_t>(welded.size()))
                                .first->second;
            }
            if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
            ++used;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t from = corner[c], to = corner[(c + 1) % 3];
                const std::uint64_t key = (static_cast<std::uint64_t>(std::min(from, to)) << 32) | std::max(from, to);
                balance[key] += from < to ? 1 : -1;
            }
        }
    }
    if (used == 0) return false;
    for (const auto& [key, walked] : balance)
        if (walked != 0) return false;
    return true;
}

std::vector<CasterLevel> simplifiedLevels(const engine::Mesh& mesh, const std::vector<bool>& readsTexcoords,
                                         const CasterLodOptions& options) {
    std::vector<CasterLevel> levels;
    const std::size_t loaded = mesh.triangleCount();
    if (loaded == 0) return levels;
    std::vector<std::vector<std::uint32_t>> sources;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const bool keepSeams = p < readsTexcoords.size() && readsTexcoords[p];
        sources.push_back(keepSeams ? mesh.primitives[p].indices : depthOnlyIndices(mesh.primitives[p]));
    }
    std::vector<SurfaceTriangle> original;  // made on first need
    std::size_t last = loaded;
    double fraction = 1.0;
    for (int attempt = 0; attempt < options.maxLevels; ++attempt) {
        fraction *= options.ratio;
        CasterLevel level;
        const double estimate = simplify(mesh, sources, fraction, options, level);
        if (level.triangles == 0) break;
        // Stuck at the error limit (or at the locked borders): coarser targets give the same.
        if (static_cast<double>(level.triangles) > options.minShrink * static_cast<double>(last)) {
            if (level.triangles >= last) break;
            continue;
        }
        if (mesh.closed && !levelIsClosed(mesh, level)) continue;
        if (original.empty()) original = meshTriangles(mesh);
        const std::vector<SurfaceTriangle> simplified = levelTriangles(mesh, level);
        // The simplifier's estimate (distances to the original's planes: at most the true
        // distance) and the last level's error are floors the bound starts from; refinement
        // stops at 25 % of the bound, or at 1e-5 of the mesh's size where both are ~0.
        const double diagonal = mesh.bounds.empty() ? 0.0 : glm::length(mesh.bounds.max - mesh.bounds.min);
        SurfaceDistanceOptions measure;
        measure.absoluteTolerance = 1e-5 * diagonal;
        measure.atLeast = std::max(estimate, levels.empty() ? 0.0 : levels.back().error);
        const double there = distanceBound(original, simplified, measure);
        measure.atLeast = std::max(measure.atLeast, there);
        // Errors only grow along the list (atLeast): choosing the coarsest level under a
        // threshold then picks a prefix.
        level.error = distanceBound(simplified, original, measure);
        last = level.triangles;
        levels.push_back(std::move(level));
    }
    return levels;
}

} // namespace shadowmap
