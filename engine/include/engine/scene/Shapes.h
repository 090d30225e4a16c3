#pragma once
// Meshes built in code (tests, the stress tool's generated scenes, key lights' helpers):
// one place for the geometry, so every generated box is closed and wound the same way.
#include "engine/scene/Scene.h"

namespace engine {

// An axis-aligned box of `size` centred at the origin: 24 vertices (flat normals, split
// along the edges as exporters do), 12 triangles wound counter-clockwise seen from
// outside. Closed once welded by position (isClosedSurface).
Primitive boxPrimitive(const glm::dvec3& size, int material = 0);

// A mesh holding one box primitive, with bounds and closedness filled in.
Mesh boxMesh(const std::string& name, const glm::dvec3& size, int material = 0);

} // namespace engine
