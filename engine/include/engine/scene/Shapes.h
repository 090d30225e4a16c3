#pragma once
// Meshes built in code (tests, the stress tool's generated scenes, key lights' helpers):
// one place for the geometry, so every generated box is closed and wound the same way.
#include "engine/scene/Scene.h"

#include <functional>
#include <string>

namespace engine {

// An axis-aligned box of `size` centred at the origin: 24 vertices (flat normals, split
// along the edges as exporters do), 12 triangles wound counter-clockwise seen from
// outside. Closed once welded by position (isClosedSurface).
Primitive boxPrimitive(const glm::dvec3& size, int material = 0);

// A mesh holding one box primitive, with bounds and closedness filled in.
Mesh boxMesh(const std::string& name, const glm::dvec3& size, int material = 0);

// A rectangle [min, max] in the XY plane (z = 0), facing +Z: 4 vertices, 2 triangles wound
// counter-clockwise seen from +Z, TEXCOORD_0 from `uvTopLeft` at (min.x, max.y) to
// `uvBottomRight` at (max.x, min.y) (glTF's convention: v grows downward, as image rows do).
// Open: give it a double-sided material to make it a caster seen from both sides.
Primitive texturedQuadPrimitive(const glm::dvec2& min, const glm::dvec2& max, int material = 0,
                                const glm::vec2& uvTopLeft = glm::vec2(0.0f),
                                const glm::vec2& uvBottomRight = glm::vec2(1.0f));

// Appends `from`'s vertices and triangles to `to` (attributes both have or both lack:
// texcoords, colors and tangents are kept only when both primitives carry them) and
// extends the bounds.
void appendPrimitive(Primitive& to, const Primitive& from);

// A width x height RGBA8 image (row 0 = top, as Image stores it) of one colour whose alpha
// is binary: 255 where opaque(column, row), else 0. The colour is the same under both, so
// filtering never blends another colour in at the mask's edges.
Image binaryAlphaImage(const std::string& name, int width, int height, const glm::u8vec3& rgb,
                       const std::function<bool(int column, int row)>& opaque);

} // namespace engine
