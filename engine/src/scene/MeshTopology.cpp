// Mesh topology: closedness (which decides whether the back-face shadow variant is valid
// for a caster) and generated normals.
#include "engine/scene/Scene.h"

#include <cassert>
#include <cstring>
#include <unordered_map>

namespace engine {

namespace {

// Exporters split vertices along hard edges and UV seams, so a cube arrives as 24 vertices
// and an index-only check would call it open. Vertices are therefore welded by exact
// position (bitwise, with -0 folded into +0) across all primitives of the mesh.
class PositionWelder {
public:
    std::uint32_t idOf(const glm::vec3& p) {
        const Key key{bits(p.x), bits(p.y), bits(p.z)};
        const auto [it, inserted] = ids_.try_emplace(key, static_cast<std::uint32_t>(ids_.size()));
        return it->second;
    }

private:
    struct Key {
        std::uint32_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = k.x;
            h = h * 0x9E3779B97F4A7C15ull ^ k.y;
            h = h * 0x9E3779B97F4A7C15ull ^ k.z;
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };
    static std::uint32_t bits(float f) {
        if (f == 0.0f) f = 0.0f;  // -0 and +0 are the same place
        std::uint32_t u;
        std::memcpy(&u, &f, sizeof u);
        return u;
    }
    std::unordered_map<Key, std::uint32_t, KeyHash> ids_;
};

// How often an undirected edge {low, high} is traversed low->high and high->low.
struct EdgeUse {
    std::uint32_t forward = 0;
    std::uint32_t backward = 0;
};

std::uint64_t edgeKey(std::uint32_t low, std::uint32_t high) {
    return (static_cast<std::uint64_t>(low) << 32) | high;
}

} // namespace

bool isClosedSurface(const Mesh& mesh) {
    PositionWelder welder;
    std::unordered_map<std::uint64_t, EdgeUse> edges;
    std::size_t usedTriangles = 0;

    for (const Primitive& primitive : mesh.primitives) {
        std::vector<std::uint32_t> welded(primitive.positions.size());
        for (std::size_t v = 0; v < welded.size(); ++v) welded[v] = welder.idOf(primitive.positions[v]);

        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            std::uint32_t corner[3];
            for (int c = 0; c < 3; ++c) {
                assert(primitive.indices[t + c] < welded.size());
                corner[c] = welded[primitive.indices[t + c]];
            }
            // A triangle that repeats a (welded) vertex has no area and no orientation:
            // strips use such triangles as joints. It neither opens nor closes anything.
            if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
            ++usedTriangles;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t from = corner[c], to = corner[(c + 1) % 3];
                EdgeUse& use = edges[edgeKey(std::min(from, to), std::max(from, to))];
                ++(from < to ? use.forward : use.backward);
            }
        }
    }
    if (usedTriangles == 0) return false;
    // Watertight and consistently wound: each edge is walked once each way.
    for (const auto& [key, use] : edges)
        if (use.forward != 1 || use.backward != 1) return false;
    return true;
}

std::vector<glm::vec3> generateNormals(const std::vector<glm::vec3>& positions,
                                       const std::vector<std::uint32_t>& indices) {
    // The unnormalized cross product is twice the triangle's area: summing it weights each
    // face by its area. Double, so large coordinates do not lose the small edge vectors.
    std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        assert(a < positions.size() && b < positions.size() && c < positions.size());
        const glm::dvec3 pa(positions[a]), pb(positions[b]), pc(positions[c]);
        const glm::dvec3 faceNormal = glm::cross(pb - pa, pc - pa);
        sums[a] += faceNormal;
        sums[b] += faceNormal;
        sums[c] += faceNormal;
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t v = 0; v < sums.size(); ++v) {
        const double length = glm::length(sums[v]);
        // A vertex touched only by degenerate triangles (or none) has no defined normal;
        // any unit vector keeps the shaders free of NaN.
        normals[v] = length > 0.0 ? glm::vec3(sums[v] / length) : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return normals;
}

} // namespace engine
