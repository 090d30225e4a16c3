#include "math/ShadowVolumeMesh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace shadowmap {

namespace {

constexpr std::uint32_t kUnset = 0xffffffffu;

// A position's bits, -0 made +0 so that the two zeros weld (they are equal positions).
struct WeldKey {
    std::uint32_t x = 0, y = 0, z = 0;
    bool operator==(const WeldKey&) const = default;
};

struct WeldKeyHash {
    std::size_t operator()(const WeldKey& k) const noexcept {
        std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
        h = (h ^ (h >> 29) ^ k.y) * 0xBF58476D1CE4E5B9ull;
        h = (h ^ (h >> 31) ^ k.z) * 0x94D049BB133111EBull;
        return std::size_t(h ^ (h >> 32));
    }
};

std::uint32_t bitsOf(float f) { return std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f); }

WeldKey keyOf(const glm::vec3& p) { return {bitsOf(p.x), bitsOf(p.y), bitsOf(p.z)}; }

// Maps input vertices to welded ones. Only positions some triangle refers to are welded: every
// frame transforms every welded vertex, so an unused one would be work for nothing.
class Welder {
public:
    explicit Welder(const std::vector<glm::vec3>& positions)
        : positions_(positions), welded_(positions.size(), kUnset) {}

    std::uint32_t weld(std::uint32_t index) {
        if (index >= positions_.size())
            throw std::invalid_argument("shadow volume mesh: index " + std::to_string(index) + " out of range (" +
                                        std::to_string(positions_.size()) + " positions)");
        if (welded_[index] != kUnset) return welded_[index];
        const glm::vec3& p = positions_[index];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("shadow volume mesh: position " + std::to_string(index) + " is not finite");
        const auto [found, added] = byPosition_.try_emplace(keyOf(p), std::uint32_t(unique_.size()));
        if (added) {
            unique_.emplace_back(p);
            sources_.push_back(index);
        }
        welded_[index] = found->second;
        return found->second;
    }

    std::vector<glm::dvec3> takePositions() { return std::move(unique_); }
    std::vector<std::uint32_t> takeSources() { return std::move(sources_); }

private:
    const std::vector<glm::vec3>& positions_;
    std::vector<std::uint32_t> welded_;
    std::unordered_map<WeldKey, std::uint32_t, WeldKeyHash> byPosition_;
    std::vector<glm::dvec3> unique_;
    std::vector<std::uint32_t> sources_;  // per welded vertex, the input vertex it was first welded from
};

// Union-find over triangles, to find a closed mesh's connected pieces.
class Pieces {
public:
    explicit Pieces(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0u); }

    std::uint32_t root(std::uint32_t t) {
        while (parent_[t] != t) t = parent_[t] = parent_[parent_[t]];
        return t;
    }

    void join(std::uint32_t s, std::uint32_t t) { parent_[root(s)] = root(t); }

private:
    std::vector<std::uint32_t> parent_;
};

// The volume's vertices for one light, each welded vertex transformed once.
struct TransformedVertices {
    std::vector<glm::vec4> finite;    // toTarget * (p, 1)
    std::vector<glm::vec4> extruded;  // toTarget * (p - light, 0), or past the bound; one shared entry when `shared`
    bool shared = false;              // a directional light without a bound: one point at infinity for all
    std::vector<std::uint8_t> unmoved;  // with a bound: per vertex, whether it is its own extruded point

    const glm::vec4& far(std::uint32_t v) const { return extruded[shared ? 0 : v]; }
    bool isUnmoved(std::uint32_t v) const { return !unmoved.empty() && unmoved[v]; }
};

// The bound is grown by this fraction of its radius: a bounding sphere touches some of the
// receivers it was made from, and they are drawn from float positions that may land a rounding
// step outside it.
constexpr double kBoundSlack = 1e-3;
// Each finite extruded vertex is pushed out along its ray by this fraction of its distance from
// the target origin (plus, for a point light, the light's): rounding the output to float moves it
// by up to 2^-24 * sqrt(3), about 1e-7, of that distance, and the far cap's guarantee is measured
// along a neighbour's direction, where a push counts at least kMinCosine of itself (below): 1e-5
// covers 1e-7 * 16 with room to spare and costs no visible fill.
constexpr double kRoundingSlack = 1e-5;
// Two vertices whose directions from a point light are this close to perpendicular or beyond
// (the cosine below it) send both to infinity: placed finitely they would have to go 16 times
// past the bound's support plane or more (at 90 degrees, to no finite distance).
constexpr double kMinCosine = 1.0 / 16.0;

bool boundGiven(const ShadowVolumeBound& bound) {
    return bound.radius > 0.0 && std::isfinite(bound.radius) && std::isfinite(bound.center.x) &&
           std::isfinite(bound.center.y) && std::isfinite(bound.center.z);
}

// A point light's extruded vertices for a bound (ShadowVolumeBound explains the distances), in
// `vertices.extruded`. target: per welded vertex, toTarget * (p, 1) in double; farCap: per
// triangle, whether it has a far cap (its corners' extrusions bound what is cut off).
void extrudePointToBound(const glm::dvec3& lightPoint, const glm::dmat4& toTarget, const ShadowVolumeBound& bound,
                         const std::vector<glm::dvec3>& positions, const std::vector<glm::dvec3>& target,
                         const std::vector<glm::u32vec3>& corners, const std::vector<std::uint8_t>& farCap,
                         TransformedVertices& vertices) {
    const glm::dvec3 light = glm::dvec3(toTarget * glm::dvec4(lightPoint, 1.0));
    const double radius = bound.radius * (1.0 + kBoundSlack);
    struct Ray {
        glm::dvec3 direction{0.0};  // unit, from the light; zero when the light is at the vertex
        double length = 0.0;        // from the light to the vertex
        double support = 0.0;       // h(direction), or 0 where the sphere is all behind the light
        double reach = 0.0;         // how far along the ray the extruded vertex must go
        bool atInfinity = false;
    };
    std::vector<Ray> rays(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        Ray& ray = rays[v];
        const glm::dvec3 toVertex = target[v] - light;
        ray.length = glm::length(toVertex);
        if (ray.length == 0.0) continue;
        ray.direction = toVertex / ray.length;
        ray.support = std::max(0.0, glm::dot(bound.center - light, ray.direction) + radius);
        ray.reach = ray.support;
    }
    // Every edge of a triangle with a far cap, from both ends (an edge shared by two such
    // triangles is seen twice: the same result, and cheaper than finding which edges qualify).
    for (std::size_t t = 0; t < corners.size(); ++t) {
        if (!farCap[t]) continue;
        const std::uint32_t c[3] = {corners[t].x, corners[t].y, corners[t].z};
        for (int i = 0; i < 3; ++i) {
            Ray& a = rays[c[i]];
            Ray& b = rays[c[(i + 1) % 3]];
            if (a.length == 0.0 || b.length == 0.0) continue;
            const double cosine = glm::dot(a.direction, b.direction);
            if (cosine < kMinCosine) {
                a.atInfinity = b.atInfinity = true;
                continue;
            }
            a.reach = std::max(a.reach, b.support / cosine);
            b.reach = std::max(b.reach, a.support / cosine);
        }
    }
    const double lightDistance = glm::length(light);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const Ray& ray = rays[v];
        if (ray.length == 0.0 || ray.atInfinity) {
            vertices.extruded[v] = glm::vec4(toTarget * glm::dvec4(positions[v] - lightPoint, 0.0));
            continue;
        }
        const double reach = ray.reach + kRoundingSlack * (ray.reach + lightDistance);
        // Already that far (the vertex is past the bound): the vertex itself, bit for bit.
        vertices.unmoved[v] = reach <= ray.length;
        vertices.extruded[v] = vertices.unmoved[v] ? vertices.finite[v]
                                                   : glm::vec4(glm::dvec4(light + ray.direction * reach, 1.0));
    }
}

// A directional light's extruded vertices for a bound: each vertex moved along the light's
// direction to the plane normal to it that touches the sphere's far side. All of them, and so
// the far cap and everything beyond it, lie past that plane, which no point of the sphere does.
void extrudeDirectionalToBound(const glm::dvec3& towardLight, const glm::dmat4& toTarget,
                               const ShadowVolumeBound& bound, const std::vector<glm::dvec3>& target,
                               TransformedVertices& vertices) {
    const glm::dvec3 away = glm::normalize(glm::dvec3(toTarget * glm::dvec4(-towardLight, 0.0)));
    const double radius = bound.radius * (1.0 + kBoundSlack);
    for (std::size_t v = 0; v < target.size(); ++v) {
        const glm::dvec3& f = target[v];
        const double distance = radius - glm::dot(f - bound.center, away);
        const double reach = distance + kRoundingSlack * (std::max(distance, 0.0) + glm::length(f));
        vertices.unmoved[v] = reach <= 0.0;
        vertices.extruded[v] = vertices.unmoved[v] ? vertices.finite[v] : glm::vec4(glm::dvec4(f + away * reach, 1.0));
    }
}

// cross(b - a, c - a) per triangle: the normals the facing test reads.
void computeNormals(const std::vector<glm::dvec3>& positions, const std::vector<glm::u32vec3>& corners,
                    std::vector<glm::dvec3>& normals) {
    normals.resize(corners.size());
    for (std::size_t t = 0; t < corners.size(); ++t) {
        const glm::u32vec3& c = corners[t];
        const glm::dvec3& a = positions[c.x];
        normals[t] = glm::cross(positions[c.y] - a, positions[c.z] - a);
    }
}

void emit(std::vector<glm::vec4>& out, const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
    out.push_back(a);
    out.push_back(b);
    out.push_back(c);
}

// The side quad on edge from -> to (the direction the volume's surface traverses it): the
// triangles (from, to, to extruded) and (from, to extruded, from extruded). For a directional
// light without a bound the second is degenerate (both points at infinity are the same) and is
// left out; with a bound, so is either one that a vertex past the bound (its own extruded point)
// collapses. A triangle with two equal corners has no area: leaving it out changes no count.
void emitSideQuad(std::vector<glm::vec4>& out, const TransformedVertices& vertices, std::uint32_t from,
                  std::uint32_t to) {
    if (!vertices.isUnmoved(to)) emit(out, vertices.finite[from], vertices.finite[to], vertices.far(to));
    if (!vertices.shared && !vertices.isUnmoved(from))
        emit(out, vertices.finite[from], vertices.far(to), vertices.far(from));
}

} // namespace

ShadowVolumeMesh::ShadowVolumeMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices) {
    if (indices.size() % 3 != 0)
        throw std::invalid_argument("shadow volume mesh: " + std::to_string(indices.size()) +
                                    " indices is not a whole number of triangles");
    // Adjacency entries are 2 * triangle + 1 in 32 bits.
    if (indices.size() / 3 >= 0x7fffffffu)
        throw std::invalid_argument("shadow volume mesh: too many triangles");
    Welder welder(positions);
    corners_.reserve(indices.size() / 3);
    for (std::size_t i = 0; i < indices.size(); i += 3) {
        const glm::u32vec3 c{welder.weld(indices[i]), welder.weld(indices[i + 1]), welder.weld(indices[i + 2])};
        if (c.x == c.y || c.y == c.z || c.z == c.x) continue;
        corners_.push_back(c);
    }
    positions_ = welder.takePositions();
    sources_ = welder.takeSources();
    inputVertexCount_ = positions.size();
    computeNormals(positions_, corners_, normals_);
    buildEdges();
    classifyClosed();
}

// Sorts the triangles' 3 * T directed edges by their undirected (a < b) pair, so each edge's
// triangles end up together: deterministic, and with no per-edge allocation.
void ShadowVolumeMesh::buildEdges() {
    struct DirectedEdge {
        std::uint64_t key;       // a << 32 | b, a < b
        std::uint32_t adjacent;  // 2 * triangle + (1 when traversed b -> a)
    };
    std::vector<DirectedEdge> directed;
    directed.reserve(3 * corners_.size());
    for (std::uint32_t t = 0; t < corners_.size(); ++t) {
        const glm::u32vec3& c = corners_[t];
        const std::uint32_t from[3] = {c.x, c.y, c.z}, to[3] = {c.y, c.z, c.x};
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = std::min(from[i], to[i]), b = std::max(from[i], to[i]);
            directed.push_back({std::uint64_t(a) << 32 | b, 2 * t + (from[i] == a ? 0u : 1u)});
        }
    }
    std::sort(directed.begin(), directed.end(), [](const DirectedEdge& l, const DirectedEdge& r) {
        return l.key != r.key ? l.key < r.key : l.adjacent < r.adjacent;
    });
    adjacency_.reserve(directed.size());
    for (std::size_t i = 0; i < directed.size(); ++i) {
        if (i == 0 || directed[i].key != directed[i - 1].key)
            edges_.push_back({std::uint32_t(directed[i].key >> 32), std::uint32_t(directed[i].key),
                              std::uint32_t(adjacency_.size())});
        adjacency_.push_back(directed[i].adjacent);
    }
}

// closed(): every edge has two triangles, one each way. closedOutward(): also every connected
// piece's signed volume (the sum of its triangles' tetrahedra to a corner of the piece) is not
// negative beyond rounding; a flat closed piece (a sheet doubled back to back) has volume 0 and
// still gets the classic volume, which is right for it.
void ShadowVolumeMesh::classifyClosed() {
    closed_ = true;
    for (std::size_t e = 0; e < edges_.size() && closed_; ++e) {
        const std::size_t begin = edges_[e].firstAdjacent;
        const std::size_t end = e + 1 < edges_.size() ? edges_[e + 1].firstAdjacent : adjacency_.size();
        closed_ = end - begin == 2 && (adjacency_[begin] & 1u) != (adjacency_[begin + 1] & 1u);
    }
    closedOutward_ = false;
    if (!closed_) return;
    Pieces pieces(corners_.size());
    for (const Edge& edge : edges_)
        pieces.join(adjacency_[edge.firstAdjacent] >> 1, adjacency_[edge.firstAdjacent + 1] >> 1);
    struct PieceVolume {
        double sum = 0.0, magnitude = 0.0;
    };
    std::unordered_map<std::uint32_t, PieceVolume> volumes;
    for (std::uint32_t t = 0; t < corners_.size(); ++t) {
        const std::uint32_t root = pieces.root(t);
        const glm::dvec3& origin = positions_[corners_[root].x];
        const glm::u32vec3& c = corners_[t];
        const double tetrahedron = glm::dot(positions_[c.x] - origin, normals_[t]);
        PieceVolume& volume = volumes[root];
        volume.sum += tetrahedron;
        volume.magnitude += std::abs(tetrahedron);
    }
    // 1e-9 of the terms' magnitudes: far above the sum's rounding (about 1e-16 per term), far
    // below any piece that truly encloses space the wrong way round (its sum is of the order of
    // its magnitude).
    closedOutward_ = std::all_of(volumes.begin(), volumes.end(),
                                 [](const auto& entry) { return entry.second.sum >= -1e-9 * entry.second.magnitude; });
}

ShadowVolumeCounts ShadowVolumeMesh::appendVolume(const glm::dvec4& light, const glm::dmat4& toTarget,
                                                  std::vector<glm::vec4>& out, const ShadowVolumeBound& bound,
                                                  VolumeCaps caps) const {
    return emitVolume(light, toTarget, positions_, normals_, out, bound, caps);
}

// The posed positions and normals are made in locals, like the other per-call buffers of
// emitVolume(): the method stays const and safe to call from several threads at once, for a
// cost (two allocations the size of the welded vertices and of the triangles) that is small
// beside the work on them (see PrintsTimeForLargeSphere).
ShadowVolumeCounts ShadowVolumeMesh::appendVolume(const glm::dvec4& light, const glm::dmat4& toTarget,
                                                  const std::vector<glm::vec3>& posed, std::vector<glm::vec4>& out,
                                                  const ShadowVolumeBound& bound, VolumeCaps caps) const {
    if (posed.size() != inputVertexCount_)
        throw std::invalid_argument("shadow volume mesh: " + std::to_string(posed.size()) +
                                    " posed positions for a mesh built from " + std::to_string(inputVertexCount_));
    std::vector<glm::dvec3> positions(sources_.size());
    for (std::size_t v = 0; v < sources_.size(); ++v) positions[v] = glm::dvec3(posed[sources_[v]]);
    std::vector<glm::dvec3> normals;
    computeNormals(positions, corners_, normals);
    return emitVolume(light, toTarget, positions, normals, out, bound, caps);
}

// positions: per welded vertex; normals: per triangle of corners_, cross(b - a, c - a) of those
// positions. Everything else (corners_, edges_, adjacency_, closedOutward_) is the mesh's.
ShadowVolumeCounts ShadowVolumeMesh::emitVolume(const glm::dvec4& light, const glm::dmat4& toTarget,
                                                const std::vector<glm::dvec3>& positions,
                                                const std::vector<glm::dvec3>& normals, std::vector<glm::vec4>& out,
                                                const ShadowVolumeBound& bound, VolumeCaps caps) const {
    ShadowVolumeCounts counts;
    const bool directional = light.w == 0.0;
    const bool bounded = boundGiven(bound);
    const glm::dvec3 lightPoint = directional ? glm::dvec3(0.0) : glm::dvec3(light) / light.w;
    const glm::dvec3 towardLight = glm::dvec3(light);

    // The classic volume's far cap is the non-facing triangles as they are; the summed
    // per-triangle volumes' far caps are every triangle turned to face the light, reversed.
    const bool classic = closedOutward_;
    // Which triangles face the light, in double: n . (light - a) > 0, or n . direction > 0.
    // A triangle whose plane passes within kEdgeOnSine of the light shows it no area and casts
    // nothing. Extruded, it would lie in its own plane and z-fight with its own surface (a point
    // light resting on a floor shadowed the whole floor). The classic volume needs every
    // triangle on one side to stay closed: it is a near cap there, pushed behind its surface by
    // the renderer like every near cap. The summed volumes leave it out: its own volume is flat.
    std::vector<std::uint8_t> facing(corners_.size()), flat(corners_.size());
    std::size_t facingCount = 0, flatCount = 0;
    for (std::size_t t = 0; t < corners_.size(); ++t) {
        const glm::dvec3 toLight = directional ? towardLight : lightPoint - positions[corners_[t].x];
        const double side = glm::dot(normals[t], toLight);
        const bool edgeOn = std::abs(side) <= kEdgeOnSine * glm::length(normals[t]) * glm::length(toLight);
        facing[t] = side > 0.0 || (classic && edgeOn);
        flat[t] = !classic && edgeOn;
        facingCount += facing[t];
        flatCount += flat[t];
    }

    TransformedVertices vertices;
    vertices.shared = directional && !bounded;
    vertices.finite.resize(positions.size());
    vertices.extruded.resize(vertices.shared ? 1 : positions.size());
    if (!bounded) {
        for (std::size_t v = 0; v < positions.size(); ++v)
            vertices.finite[v] = glm::vec4(toTarget * glm::dvec4(positions[v], 1.0));
        if (directional)
            vertices.extruded[0] = glm::vec4(toTarget * glm::dvec4(-towardLight, 0.0));
        else
            for (std::size_t v = 0; v < positions.size(); ++v)
                vertices.extruded[v] = glm::vec4(toTarget * glm::dvec4(positions[v] - lightPoint, 0.0));
    } else {
        // The bound is in target space, which toTarget may scale unevenly: the distances are
        // measured there, on the vertices transformed in double.
        std::vector<glm::dvec3> target(positions.size());
        vertices.unmoved.resize(positions.size());
        for (std::size_t v = 0; v < positions.size(); ++v) {
            const glm::dvec4 f = toTarget * glm::dvec4(positions[v], 1.0);
            vertices.finite[v] = glm::vec4(f);
            target[v] = glm::dvec3(f);
        }
        if (directional) {
            extrudeDirectionalToBound(towardLight, toTarget, bound, target, vertices);
        } else {
            std::vector<std::uint8_t> farCap(corners_.size());
            for (std::size_t t = 0; t < corners_.size(); ++t) farCap[t] = classic ? !facing[t] : !flat[t];
            extrudePointToBound(lightPoint, toTarget, bound, positions, target, corners_, farCap, vertices);
        }
    }

    // Either way a far cap triangle is (x, y, z) or (x, z, y) extruded; none for a directional
    // light without a bound, where all three corners are the same point.
    const bool capsEmitted = !(classic && caps == VolumeCaps::LeftOutIfClosed);
    const std::size_t nearCount = !capsEmitted ? 0 : classic ? facingCount : corners_.size() - flatCount;
    const std::size_t farCount =
        !capsEmitted || vertices.shared ? 0 : (classic ? corners_.size() - facingCount : nearCount);
    out.reserve(out.size() + 3 * (nearCount + farCount));
    for (std::size_t t = 0; capsEmitted && t < corners_.size(); ++t) {
        if (flat[t]) continue;
        const glm::u32vec3& c = corners_[t];
        if (facing[t])
            emit(out, vertices.finite[c.x], vertices.finite[c.y], vertices.finite[c.z]);
        else if (!classic)
            emit(out, vertices.finite[c.x], vertices.finite[c.z], vertices.finite[c.y]);
        if (vertices.shared || (classic && facing[t])) continue;
        if (facing[t])
            emit(out, vertices.far(c.x), vertices.far(c.z), vertices.far(c.y));
        else
            emit(out, vertices.far(c.x), vertices.far(c.y), vertices.far(c.z));
    }
    counts.capTriangles = nearCount + farCount;

    // Side quads. Each near cap triangle traverses its edges one way; the surface closes with
    // a quad traversing the edge the other way. The edge's multiplicity m sums, over its
    // triangles that have a near cap, +1 for a cap traversing it a -> b, -1 for b -> a (a
    // classic silhouette edge: +-1; a summed edge: what does not cancel). m > 0: |m| quads on
    // b -> a; m < 0: |m| quads on a -> b.
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        const std::size_t begin = edges_[e].firstAdjacent;
        const std::size_t end = e + 1 < edges_.size() ? edges_[e + 1].firstAdjacent : adjacency_.size();
        long m = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t t = adjacency_[i] >> 1;
            const long way = (adjacency_[i] & 1u) ? -1 : 1;
            if (flat[t]) continue;
            if (facing[t])
                m += way;
            else if (!classic)
                m -= way;
        }
        const Edge& edge = edges_[e];
        for (long k = 0; k < std::labs(m); ++k) {
            if (m > 0)
                emitSideQuad(out, vertices, edge.b, edge.a);
            else
                emitSideQuad(out, vertices, edge.a, edge.b);
        }
        counts.silhouetteEdges += std::uint64_t(std::labs(m));
    }
    return counts;
}

std::vector<std::uint32_t> ShadowVolumeMesh::adjacencyIndices() const {
    if (!closedOutward_) return {};
    std::vector<std::uint32_t> indices(6 * corners_.size());
    for (std::size_t t = 0; t < corners_.size(); ++t)
        for (int k = 0; k < 3; ++k) indices[6 * t + 2 * k] = corners_[t][k];
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        const std::size_t begin = edges_[e].firstAdjacent;  // closed: exactly two triangles
        const std::uint32_t triangles[2] = {adjacency_[begin] >> 1, adjacency_[begin + 1] >> 1};
        for (int side = 0; side < 2; ++side) {
            const glm::u32vec3& here = corners_[triangles[side]];
            const glm::u32vec3& across = corners_[triangles[1 - side]];
            std::uint32_t opposite = across.x;
            for (int k = 0; k < 3; ++k)
                if (across[k] != edges_[e].a && across[k] != edges_[e].b) opposite = across[k];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t from = here[k], to = here[(k + 1) % 3];
                if ((from == edges_[e].a && to == edges_[e].b) || (from == edges_[e].b && to == edges_[e].a))
                    indices[6 * triangles[side] + 2 * k + 1] = opposite;
            }
        }
    }
    return indices;
}

} // namespace shadowmap
