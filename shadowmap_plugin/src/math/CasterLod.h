#pragma once
// A shadow caster's simplified levels (caster_lod): index lists into the SAME vertices as the
// mesh as loaded, made by meshoptimizer's simplifier, each with a bound of its geometric
// error. Same vertices means whatever is per vertex keeps working at every level: skinning
// and morphing deform the level's vertices (simplified in bind pose), alpha-masked casters
// keep their UVs. No GL.
//
// Levels halve the triangle count each (the simplifier stops short where its own error
// estimate passes kMaxRelativeError of the primitive's size); a level that is not at least
// a quarter smaller than the last one kept ends the list. Primitive borders are locked
// (meshopt_SimplifyLockBorder), so the primitives of a mesh stay stitched to each other. A
// closed mesh (Mesh::closed) keeps only closed levels (levelIsClosed): backface culls front
// faces and woo peels two layers, and both need every ray through the caster to cross it
// an even number of times.
//
// Error: the simplifier's estimate is relative and not a bound, so each level's error is
// measured against the mesh as loaded, both ways (math/SurfaceDistance.h: the largest
// distance from a point of either surface to the other, bounded from above), in the mesh's
// object units. Where a level sits at that distance, the shadow's silhouette moves by at most
// as much (times the instance's scale).
#include "engine/scene/Scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowmap {

struct CasterLevel {
    // Per Mesh::primitives, a triangle list into that primitive's vertices (empty where the
    // primitive is empty).
    std::vector<std::vector<std::uint32_t>> indices;
    double error = 0.0;  // object units: the two-sided distance bound to the mesh as loaded
    std::size_t triangles = 0;
};

struct CasterLodOptions {
    // Each level aims at this fraction of the last one's triangles.
    double ratio = 0.5;
    // A level is kept only if it has at most this fraction of the last kept one's triangles.
    double minShrink = 0.75;
    // The simplifier's target error, relative to each primitive's extent: beyond it a level
    // changes a caster's shape too much to be worth a draw at any texel size.
    double maxRelativeError = 0.05;
    int maxLevels = 8;
};

// The levels coarser than the mesh as loaded, finest first (errors grow, triangles shrink).
// Empty when the mesh cannot be simplified by enough. readsTexcoords, per primitive (missing:
// false): its depth pass samples a texture (alpha-masked), so its levels keep its vertices
// as they are, UV seams included; the others are simplified with vertices that deform
// alike welded (only positions reach an opaque caster's depth), each welded corner one of
// the vertices it stands for.
std::vector<CasterLevel> simplifiedLevels(const engine::Mesh& mesh, const std::vector<bool>& readsTexcoords = {},
                                         const CasterLodOptions& options = {});

// Whether the mesh, with each primitive's triangles replaced by the level's, is closed for
// a shadow: welded by position (degenerate triangles ignored), every edge is walked as
// often one way as the other, so every ray enters the solid as often as it leaves it. That
// is engine::isClosedSurface (each edge once each way) except that it also accepts what the
// simplifier makes of a thin part, two sheets pinched along an edge (walked twice each
// way): parity, which woo's two layers and backface's back faces rest on, is kept there.
bool levelIsClosed(const engine::Mesh& mesh, const CasterLevel& level);

// The mesh's triangles (all primitives) in object space, and a level's.
std::vector<std::array<glm::dvec3, 3>> meshTriangles(const engine::Mesh& mesh);
std::vector<std::array<glm::dvec3, 3>> levelTriangles(const engine::Mesh& mesh, const CasterLevel& level);

} // namespace shadowmap
