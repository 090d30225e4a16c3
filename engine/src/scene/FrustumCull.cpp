#include "engine/scene/FrustumCull.h"

#include <glm/gtc/matrix_access.hpp>

namespace engine {

std::array<glm::dvec4, 6> frustumPlanes(const glm::dmat4& m) {
    // Clip-space point c = m * x is inside when -w <= x,y,z <= w; each inequality is a
    // plane in the source space: (row3 +/- row_i) . x >= 0.
    const glm::dvec4 r0 = glm::row(m, 0), r1 = glm::row(m, 1), r2 = glm::row(m, 2),
                     r3 = glm::row(m, 3);
    return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
}

bool boxIntersectsFrustum(const glm::dmat4& viewProjection, const Aabb& box) {
    if (box.empty()) return false;
    for (const glm::dvec4& plane : frustumPlanes(viewProjection)) {
        // The box corner farthest along the plane normal; if even it is outside, all are.
        const glm::dvec3 p(plane.x >= 0.0 ? box.max.x : box.min.x,
                           plane.y >= 0.0 ? box.max.y : box.min.y,
                           plane.z >= 0.0 ? box.max.z : box.min.z);
        if (plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w < 0.0) return false;
    }
    return true;
}

}  // namespace engine
