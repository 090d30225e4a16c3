#pragma once
// Frustum planes from a view-projection matrix (Gribb & Hartmann) and a conservative
// box-versus-frustum test, for light frusta (shadow plugin) and camera culling alike. No GL.
#include "engine/scene/Aabb.h"

#include <array>
#include <glm/glm.hpp>

namespace engine {

// The six planes (a,b,c,d) with a*x + b*y + c*z + d >= 0 inside, in the space the matrix
// takes points from (world space for P * view): left, right, bottom, top, near, far.
// OpenGL clip convention (-w <= z <= w); for a [0,1]-depth matrix the near test is looser,
// i.e. still conservative. Planes are not normalized (the sign test does not need it).
std::array<glm::dvec4, 6> frustumPlanes(const glm::dmat4& viewProjection);

// False only when the box lies entirely outside one of the six planes. Conservative: a
// box near a frustum corner (outside, but not behind any single plane) counts as inside.
// An empty box is outside.
bool boxIntersectsFrustum(const glm::dmat4& viewProjection, const Aabb& box);

}  // namespace engine
