#include "math/SurfaceDistance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace shadowmap {

namespace {

// The covering radius of a triangle's corners over its longest edge (1/sqrt(3), rounded up).
constexpr double kCoverRadius = 0.6;

glm::dvec3 closestPoint(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {  // degenerate: the nearest of its edges
        const auto onSegment = [&p](const glm::dvec3& from, const glm::dvec3& to) {
            const glm::dvec3 d = to - from;
            const double length2 = glm::dot(d, d);
            const double t = length2 > 0.0 ? std::clamp(glm::dot(p - from, d) / length2, 0.0, 1.0) : 0.0;
            return from + d * t;
        };
        glm::dvec3 best = onSegment(a, b);
        for (const glm::dvec3& q : {onSegment(b, c), onSegment(c, a)})
            if (glm::length(p - q) < glm::length(p - best)) best = q;
        return best;
    }
    return a + ab * (vb / sum) + ac * (vc / sum);
}

// Triangles binned by their boxes into a uniform grid over `bounds`, for nearest queries.
class TriangleGrid {
public:
    TriangleGrid(const std::vector<SurfaceTriangle>& triangles, const glm::dvec3& lo, const glm::dvec3& hi)
        : triangles_(triangles), lo_(lo), seen_(triangles.size(), 0) {
        const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-12));
        // About two triangles per cell the surface passes through: cells as wide as two mean
        // triangles are across (a volume-based size puts dozens in each cell of a thin shell),
        // at most 2^20 per side. Only those cells are stored.
        double area = 0.0;
        for (const SurfaceTriangle& t : triangles) area += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        const double longest = std::max({extent.x, extent.y, extent.z});
        double cell = std::sqrt(2.0 * area / std::max<std::size_t>(triangles.size(), 1));
        cell = std::max(cell, longest / double(1 << 20));
        cell_ = cell;
        for (int axis = 0; axis < 3; ++axis) dims_[axis] = std::max(1, static_cast<int>(std::ceil(extent[axis] / cell)));
        dims_ = glm::min(dims_, glm::ivec3(1 << 20));
        for (std::uint32_t t = 0; t < triangles.size(); ++t) {
            const SurfaceTriangle& tri = triangles[t];
            const glm::ivec3 from = cellOf(glm::min(tri[0], glm::min(tri[1], tri[2])));
            const glm::ivec3 to = cellOf(glm::max(tri[0], glm::max(tri[1], tri[2])));
            for (int z = from.z; z <= to.z; ++z)
                for (int y = from.y; y <= to.y; ++y)
                    for (int x = from.x; x <= to.x; ++x) cells_[key({x, y, z})].push_back(t);
        }
    }

    struct Hit {
        double distance = std::numeric_limits<double>::infinity();
        std::uint32_t triangle = 0;
    };
    // The nearest triangle and its distance, or some triangle within `enough` once one that
    // near is found (the caller needs no more).
    Hit nearest(const glm::dvec3& p, double enough) {
        ++stamp_;
        const glm::ivec3 centre = cellOf(p);
        // The distance from p to its cell's walls: what ring k guarantees beyond it.
        const glm::dvec3 local = p - (lo_ + glm::dvec3(centre) * cell_);
        const double inner = std::max(0.0, std::min({local.x, local.y, local.z, cell_ - local.x, cell_ - local.y,
                                                     cell_ - local.z}));
        Hit best;
        const int rings = std::max({dims_.x, dims_.y, dims_.z});
        for (int k = 0; k <= rings; ++k) {
            for (int z = centre.z - k; z <= centre.z + k; ++z)
                for (int y = centre.y - k; y <= centre.y + k; ++y)
                    for (int x = centre.x - k; x <= centre.x + k; ++x) {
                        const bool shell = std::abs(x - centre.x) == k || std::abs(y - centre.y) == k ||
                                           std::abs(z - centre.z) == k;
                        if (!shell || x < 0 || y < 0 || z < 0 || x >= dims_.x || y >= dims_.y || z >= dims_.z) continue;
                        const auto cell = cells_.find(key({x, y, z}));
                        if (cell == cells_.end()) continue;
                        for (const std::uint32_t t : cell->second) {
                            if (seen_[t] == stamp_) continue;
                            seen_[t] = stamp_;
                            const double distance = pointTriangleDistance(p, triangles_[t]);
                            if (distance < best.distance) best = {distance, t};
                            if (best.distance <= enough) return best;
                        }
                    }
            // Every triangle not met yet lies outside the (2k+1)^3 block around p's cell.
            if (best.distance <= inner + k * cell_) return best;
        }
        return best;
    }

private:
    glm::ivec3 cellOf(const glm::dvec3& p) const {
        const glm::dvec3 cell = glm::floor((p - lo_) / cell_);
        return glm::clamp(glm::ivec3(cell), glm::ivec3(0), dims_ - 1);
    }
    static std::uint64_t key(const glm::ivec3& c) {
        return (static_cast<std::uint64_t>(c.z) << 42) | (static_cast<std::uint64_t>(c.y) << 21) |
               static_cast<std::uint64_t>(c.x);
    }

public:
    const std::vector<SurfaceTriangle>& triangles_;

private:
    glm::dvec3 lo_;
    double cell_ = 1.0;
    glm::ivec3 dims_{1};
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
};

double longestEdge(const SurfaceTriangle& t) {
    return std::max({glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
}

} // namespace

double pointTriangleDistance(const glm::dvec3& p, const SurfaceTriangle& triangle) {
    return glm::length(p - closestPoint(p, triangle[0], triangle[1], triangle[2]));
}

namespace {

// The branch and bound of one triangle (see SurfaceDistance.h), raising `bound`.
void refine(const SurfaceTriangle& t, int depth, TriangleGrid& grid, const SurfaceDistanceOptions& options,
            double& bound) {
    const double radius = kCoverRadius * longestEdge(t);
    // Any triangle of `to` near a corner: the distance to one triangle is convex, so over
    // this piece it is at most its largest value at the corners.
    std::array<TriangleGrid::Hit, 3> hits;
    for (int c = 0; c < 3; ++c) hits[c] = grid.nearest(t[c], bound);
    double convex = std::numeric_limits<double>::infinity();
    for (const TriangleGrid::Hit& hit : hits) {
        double largest = 0.0;
        for (const glm::dvec3& corner : t)
            largest = std::max(largest, pointTriangleDistance(corner, grid.triangles_[hit.triangle]));
        convex = std::min(convex, largest);
    }
    if (convex <= bound) return;
    const double tolerance = std::max(options.absoluteTolerance, options.relativeTolerance * bound);
    if (radius <= tolerance || depth >= options.maxDepth) {
        double corners = 0.0;  // exact now: the early answers may be any triangle within reach
        for (const glm::dvec3& corner : t) corners = std::max(corners, grid.nearest(corner, 0.0).distance);
        bound = std::max(bound, std::min(convex, corners + radius));
        return;
    }
    const glm::dvec3 ab = (t[0] + t[1]) * 0.5, bc = (t[1] + t[2]) * 0.5, ca = (t[2] + t[0]) * 0.5;
    for (const SurfaceTriangle& piece : {SurfaceTriangle{t[0], ab, ca}, SurfaceTriangle{ab, t[1], bc},
                                         SurfaceTriangle{ca, bc, t[2]}, SurfaceTriangle{ab, bc, ca}})
        refine(piece, depth + 1, grid, options, bound);
}

} // namespace

double distanceBound(const std::vector<SurfaceTriangle>& from, const std::vector<SurfaceTriangle>& to,
                     const SurfaceDistanceOptions& options) {
    if (from.empty()) return options.atLeast;
    if (to.empty()) return std::numeric_limits<double>::infinity();
    // The grid spans both surfaces, so every corner lies inside it (the ring bound needs that).
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const auto* surface : {&from, &to})
        for (const SurfaceTriangle& t : *surface)
            for (const glm::dvec3& corner : t) {
                lo = glm::min(lo, corner);
                hi = glm::max(hi, corner);
            }
    TriangleGrid grid(to, lo, hi);
    // First the distances of some triangles' corners and centroids: true distances, so a
    // floor the refinement starts from; pieces nearer than it need no splitting. Every 8th
    // triangle gives most of the floor for an eighth of the queries.
    double bound = options.atLeast;
    for (std::size_t i = 0; i < from.size(); i += 8) {
        const SurfaceTriangle& t = from[i];
        for (const glm::dvec3& p : {t[0], t[1], t[2], (t[0] + t[1] + t[2]) / 3.0})
            bound = std::max(bound, grid.nearest(p, bound).distance);
    }
    for (const SurfaceTriangle& t : from) refine(t, 0, grid, options, bound);
    return bound;
}

} // namespace shadowmap
