#pragma once
// Stenciled shadow volumes (Everitt & Kilgard, "Practical and Robust Stenciled Shadow Volumes
// for Hardware-Accelerated Rendering", 2002) built on the CPU from a triangle mesh: the
// triangles of the closed surface that bounds the region a mesh shadows from one light, for the
// z-fail (Carmack's reverse) stencil count. No GL: the plugin draws what appendVolume() emits.
//
// Extrusion to infinity: each extruded vertex is a homogeneous point with w = 0 (the direction
// away from the light), so the volume is closed without a far distance and a projection with an
// infinite far plane never clips it. Or, given a ShadowVolumeBound (a sphere holding every point
// whose count matters), extrusion to finite points just past it: the same counts inside the
// sphere for far less fill outside it. The mesh's edge adjacency is built once at load; each
// frame only classifies the triangles and walks the edges, O(triangles + edges).
//
// Two formulations, chosen per mesh at load:
//  - Closed and wound outward (closedOutward()): the classic volume. The near cap is the
//    triangles that face the light, the far cap the others extruded to infinity, and a side quad
//    stands on each silhouette edge (between a facing and a non-facing triangle). Inside it the
//    count is the number of times the segment from the light (the ray toward a directional
//    light) enters the solid: 0 when lit, 1 behind a convex caster. The less fill of the two.
//  - Anything else (open, non-manifold, or a closed piece wound inward such as a single-shell
//    room seen from inside): the sum of every triangle's own volume. Each triangle is turned to
//    face the light; its near cap is itself, its far cap itself extruded with reversed winding;
//    the side quads of one edge from all its triangles are summed, so an edge inside a region
//    that faces one way cancels and an edge where the surface folds away from the light gets
//    two quads. Inside it the count is the number of triangles the segment from the light
//    crosses, whichever side faces the light: a two-sided sheet shadows from both sides. The
//    classic volume would be wrong here: it needs a closed boundary, and it counts entries into
//    the solid the fronts face away from, which for an inward-wound room is the world outside:
//    lit from inside, the whole room would count -1 and the outside 0; lit from outside, the
//    room 0. Non-zero means shadowed in both formulations, as the z-fail stencil test asks.
// A light inside the solid of a closed outward mesh (a point light inside a closed bulb) gives
// the count 1 everywhere outside it: shadowed, as an opaque shell around the light would.
//
// Winding: every emitted triangle is counter-clockwise seen from outside the volume it bounds,
// in the mesh's object space, so the count is +1 inside (what the stencil ops assume). When
// toTarget mirrors (negative determinant), the caller flips the front face as for any mirrored
// draw. The math is in double so that a mesh far from the origin, carried to camera-relative
// coordinates by toTarget, loses nothing before the single rounding to float.
//
// Directional lights extrude every vertex to the same point at infinity, so the far cap and
// one of the two triangles of each side quad are degenerate by construction; they are not
// emitted, to save fill. With a bound the extruded vertices are distinct finite points, and the
// far cap and both halves of each side quad are emitted (still less fill than a volume reaching
// to infinity).
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace shadowmap {

// The sine of the angle between a triangle's plane and the direction to the light below which
// the triangle counts as edge-on (it casts nothing; emitVolume): its shadow would be a sliver this
// wide, far under a pixel, while float rounding of a light placed on a surface reaches about 1e-7.
// The geometry shader that makes the same volume on the GPU reads it too (EDGE_ON_SINE).
inline constexpr double kEdgeOnSine = 1e-6;

struct ShadowVolumeCounts {
    std::uint64_t silhouetteEdges = 0;  // side quads emitted (an edge of multiplicity 2 counts 2)
    std::uint64_t capTriangles = 0;     // near + far cap triangles emitted
};

// Where the volume may end: a sphere in the TARGET space (after toTarget) holding every point
// whose count matters (the receivers the camera sees). With one, each extruded vertex is a finite
// point (w = 1) on the ray from the light through its vertex, far enough that the ray has left
// the sphere: the volume is exact inside the sphere and ends a little past it, so its side quads
// and far cap cover less of the screen. Without one (radius <= 0 or no bound), extrusion to
// infinity (w = 0) as before; a bound that is not finite counts as none.
//
// Far enough is more than the ray having left the sphere: the far cap and the side quads' far
// edges are straight between extruded vertices, and a chord between two points past the sphere
// still cuts through it when their rays are far apart (a light close to a large triangle, or
// inside the sphere: a chord of a wide angle). So, for a point light, with u the unit direction
// from the light to a vertex and h(u) = (c - light) . u + R the distance from the light to the
// plane normal to u that touches the sphere's far side, a vertex goes at least h(u) along its ray,
// and at least h(u') / (u . u') for each neighbour u' along an edge of a triangle that has a far
// cap. Then all corners of such a triangle lie past the plane of any one corner's u, and so does
// its far cap and everything beyond it along the rays: the part of the infinite volume that is cut
// off holds no point of the sphere. A vertex with such a neighbour nearly 90 degrees or more away
// seen from the light (u . u' < 1/16: it would have to go 16 times past the plane, or to no
// finite distance) stays at infinity (w = 0) as without a bound, which mixes with the finite
// ones: its direction still leads past that plane. A directional light needs no neighbours: each
// vertex goes along the light's direction to the plane normal to it that touches the sphere's far
// side. A vertex already past is its own extruded point, and the halves of side quads that it
// collapses are left out (no area).
//
// Margins, against rounding: the sphere is taken 1e-3 of R larger (receivers on it are drawn from
// float positions a rounding step off), and each extruded vertex goes 1e-5 of its distance from the
// target origin further (the output's rounding to float moves it by about 1e-7 of that).
// toTarget must be affine (last row 0, 0, 0, 1), as model-view matrices are, when a bound is given:
// the distances are measured on its xyz.
struct ShadowVolumeBound {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Whether a classic volume's caps are emitted. Counted with z-pass (the volume faces in front of
// each pixel's surface, for a camera outside every volume), a closed outward caster's caps never
// count: its near cap is its own lit surface, behind which nothing of it is seen, and its far cap
// lies past every receiver (at the bound or at infinity). z-fail needs them. The summed
// per-triangle volumes always keep theirs: an open surface can be seen through from behind.
enum class VolumeCaps { Emitted, LeftOutIfClosed };

// A mesh's edge adjacency, built once at load, from which each frame's volume is extruded.
class ShadowVolumeMesh {
public:
    ShadowVolumeMesh() = default;
    // positions: object space; indices: a triangle list (3 per triangle) into positions.
    // Vertices are welded by exact position equality first (glTF splits vertices by normal/UV;
    // -0 and +0 are equal). Degenerate triangles (two equal welded corners) are dropped.
    // Throws std::invalid_argument when indices.size() is not a multiple of 3, an index is out
    // of range, or a used position is not finite.
    ShadowVolumeMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices);

    // Every edge has exactly two triangles that traverse it in opposite directions.
    bool closed() const { return closed_; }
    // closed() and every connected piece encloses a non-negative volume (wound outward): the
    // meshes that get the classic volume.
    bool closedOutward() const { return closedOutward_; }
    std::size_t triangleCount() const { return corners_.size(); }
    std::size_t edgeCount() const { return edges_.size(); }
    std::size_t vertexCount() const { return positions_.size(); }  // after welding

    // For extrusion on the GPU (a geometry shader reading GL_TRIANGLES_ADJACENCY): the welded
    // positions, and per triangle six indices into them, each corner followed by the vertex of
    // the triangle across the edge from that corner to the next, opposite that edge. Only a
    // closedOutward() mesh has exactly one triangle across every edge and gets the classic
    // volume a shader can make per triangle: empty for any other.
    const std::vector<glm::dvec3>& weldedPositions() const { return positions_; }
    std::vector<std::uint32_t> adjacencyIndices() const;

    // Appends the shadow volume's triangles to `out` as homogeneous points: each finite vertex
    // is toTarget * (p, 1), each extruded vertex at infinity is toTarget * (p - light.xyz, 0) for
    // a light at a point (light.w == 1), or toTarget * (-light.xyz, 0) for a directional light
    // (light.w == 0, light.xyz = direction TOWARD the light). `light` is in the mesh's object
    // space. All math in double; the output rounded to float at the end.
    // Every emitted triangle is wound counter-clockwise seen from outside the volume it bounds.
    // A light exactly at a vertex extrudes that vertex to (0, 0, 0, 0): keep lights off casters.
    // With a bound (see ShadowVolumeBound), the extruded vertices are finite points past it
    // instead (a few may stay at infinity as above), and the counts are exact inside it only;
    // counts.silhouetteEdges still counts a quad whose collapsed halves are left out. A light at a
    // vertex (in target space) keeps (0, 0, 0, 0) for that vertex and constrains no other.
    ShadowVolumeCounts appendVolume(const glm::dvec4& light, const glm::dmat4& toTarget, std::vector<glm::vec4>& out,
                                    const ShadowVolumeBound& bound = {},
                                    VolumeCaps caps = VolumeCaps::Emitted) const;

    // The same volume for the mesh posed: `posed` holds a position per input vertex (the
    // constructor's `positions` indexing, same size), e.g. a skinned or morphed pose. The
    // adjacency (welding, edges, closedness) is the one built from the rest positions; each welded
    // vertex takes the posed position of the input vertex it was first welded from. Throws
    // std::invalid_argument when posed.size() differs from the constructor's positions.size().
    // Posed with the rest positions, the output is the other overload's, bit for bit.
    //
    // Seams: input vertices welded at rest may be posed apart (copies of a seam vertex with
    // different skin weights or morph targets). They stay one vertex, at the posed position of
    // the first of them the indices refer to (in index order); the other copies' posed positions
    // are not read, so the surface cannot tear at a seam and a closed mesh stays closed by
    // construction. Positions no triangle uses are not read either. Posed positions are not
    // checked: a non-finite one gives non-finite output. Triangles dropped at rest stay dropped;
    // one the pose collapses faces no light and shadows nothing, as its geometry says.
    //
    // Folds: closedOutward(), and so the formulation, is decided at rest and kept: a pose keeps
    // the topology, so the posed surface is still closed and consistently wound, but it may cross
    // itself or turn inside out. The summed per-triangle volumes count the triangles crossed
    // whatever the pose: exact. The classic volume counts, at a point q, the triangles facing the
    // light that the segment from q to the light crosses, plus the posed surface's winding number
    // at the light (0 outside the solid and for a directional light); equivalently w(q) + n(q),
    // w(q) the posed surface's winding number at q, n(q) the triangles facing away from the light
    // that the segment crosses. With the light outside the solid:
    //  - A pose that folds the surface into itself without turning any of it inside out (an arm
    //    crossing the body: w = 2 in the overlap) keeps w >= 0 everywhere, and the count is
    //    non-zero exactly in shadow, as at rest (2 behind the overlap).
    //  - A pose that turns part of the surface inside out (a face pushed through the opposite one,
    //    skin folded over itself at a joint bent too far) makes w < 0 in that part. Outside it the
    //    count stays right; inside it, it is 0 wherever the segment crosses only triangles facing
    //    away from the light: points in shadow there read as lit. Those counts are wrong, and a
    //    per-frame signed volume would not catch it (a small turned part leaves it positive).
    // The rest overload's caveats (light inside the solid, light at a vertex) hold as well.
    // Const and thread-safe like the rest overload: the posed positions and normals go in per-call
    // buffers. Each call gathers the pose and recomputes the triangles' normals: O(vertices +
    // triangles) on top of the rest overload's work.
    ShadowVolumeCounts appendVolume(const glm::dvec4& light, const glm::dmat4& toTarget,
                                    const std::vector<glm::vec3>& posed, std::vector<glm::vec4>& out,
                                    const ShadowVolumeBound& bound = {},
                                    VolumeCaps caps = VolumeCaps::Emitted) const;

private:
    // An undirected edge between welded vertices a < b; its triangles are
    // adjacency_[firstAdjacent .. next edge's firstAdjacent), each 2 * triangle + (1 when that
    // triangle traverses the edge b -> a, 0 when a -> b).
    struct Edge {
        std::uint32_t a = 0, b = 0;
        std::uint32_t firstAdjacent = 0;
    };

    void buildEdges();
    void classifyClosed();
    // The one implementation of both appendVolume() overloads. positions: per welded vertex;
    // normals: per triangle, cross(b - a, c - a) of those positions.
    ShadowVolumeCounts emitVolume(const glm::dvec4& light, const glm::dmat4& toTarget,
                                  const std::vector<glm::dvec3>& positions, const std::vector<glm::dvec3>& normals,
                                  std::vector<glm::vec4>& out, const ShadowVolumeBound& bound, VolumeCaps caps) const;

    std::vector<glm::dvec3> positions_;                // welded, object space
    std::vector<std::uint32_t> sources_;               // per welded vertex, the input vertex first welded into it
    std::size_t inputVertexCount_ = 0;                 // the constructor's positions.size()
    std::vector<glm::u32vec3> corners_;                // per triangle, welded indices, as given
    std::vector<glm::dvec3> normals_;                  // per triangle, cross(b - a, c - a)
    std::vector<Edge> edges_;
    std::vector<std::uint32_t> adjacency_;             // see Edge; one past the last: adjacency_.size()
    bool closed_ = false;
    bool closedOutward_ = false;
};

} // namespace shadowmap
