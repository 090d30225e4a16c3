#pragma once
// An upper bound of the one-sided distance from one triangle surface to another: the
// largest distance from a point of `from` to the nearest point of `to` (one side of the
// Hausdorff distance). What a simplified caster level's recorded error is made of
// (math/CasterLod.h), so it must never be below the truth.
//
// Branch and bound over each triangle of `from`, split in four while undecided. Two upper
// bounds of the distance over a piece, the smaller counts:
//  - convexity: the distance to ONE triangle of `to` is a convex function, so over the piece
//    it is at most its largest value at the piece's corners; the triangles nearest each
//    corner are tried. Where the piece lies over one triangle of `to` this is tight;
//  - Lipschitz: the distance to a surface changes by at most the distance moved, so every
//    point is within (largest corner distance) + r, r = 0.6 x the longest edge (the farthest
//    a point of a triangle can be from its nearest corner is longest / sqrt(3) = 0.577).
// A piece whose bound cannot raise the largest distance found so far is done; one whose r
// is within the tolerance raises it by its bound. Distances are exact point-to-triangle
// distances in double.
#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace shadowmap {

using SurfaceTriangle = std::array<glm::dvec3, 3>;

struct SurfaceDistanceOptions {
    // Refinement stops where r <= max(absoluteTolerance, relativeTolerance * bound): the
    // bound exceeds the true distance by at most about that much.
    double absoluteTolerance = 0.0;
    double relativeTolerance = 0.25;
    int maxDepth = 6;  // splits of one input triangle at most (4^6 pieces)
    // A value known to be at most the answer wanted (0, or an error the caller records
    // anyway): pieces that cannot exceed it are not refined, which makes the bound cheap
    // where surfaces coincide. The result is max(atLeast, the bound).
    double atLeast = 0.0;
};

// Upper bound of max(atLeast, max_{p in from} min_{q in to} |p - q|); atLeast when `from` is empty, infinity
// when `to` is empty and `from` is not.
double distanceBound(const std::vector<SurfaceTriangle>& from, const std::vector<SurfaceTriangle>& to,
                     const SurfaceDistanceOptions& options = {});

// The exact distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision
// Detection 5.1.5), in double.
double pointTriangleDistance(const glm::dvec3& p, const SurfaceTriangle& triangle);

} // namespace shadowmap
