#include "technique/CasterLodChoice.h"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmap {

double texelSizeAt(const glm::dmat4& viewProjection, const engine::Aabb& worldBounds, int resolution) {
    if (worldBounds.empty() || resolution <= 0) return 0.0;
    const glm::dvec4 rowX = glm::row(viewProjection, 0), rowY = glm::row(viewProjection, 1),
                     rowW = glm::row(viewProjection, 3);
    double smallest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p(worldBounds.corner(i), 1.0);
        const double w = glm::dot(rowW, p);
        if (!(w > 0.0)) return 0.0;
        const double x = glm::dot(rowX, p) / w, y = glm::dot(rowY, p) / w;
        // |d(x/w)/dp| = |rowX.xyz - (x/w) rowW.xyz| / w: NDC units per world unit.
        const double gradient = std::max(glm::length(glm::dvec3(rowX) - x * glm::dvec3(rowW)),
                                         glm::length(glm::dvec3(rowY) - y * glm::dvec3(rowW))) / w;
        if (!(gradient > 0.0)) continue;
        smallest = std::min(smallest, (2.0 / resolution) / gradient);
    }
    return std::isfinite(smallest) ? smallest : 0.0;
}

double largestScale(const glm::dmat4& world) {
    const glm::dmat3 m(world);
    const glm::dmat3 gram = glm::transpose(m) * m;
    // Power iteration on M^T M from a start no column of a rotation can be orthogonal to for
    // long; 32 steps reach the largest eigenvalue to well under 1e-6 for the scales that occur.
    glm::dvec3 v(0.577, 0.579, 0.575);
    double eigen = 0.0;
    for (int step = 0; step < 32; ++step) {
        const glm::dvec3 next = gram * v;
        const double length = glm::length(next);
        if (!(length > 0.0)) return 0.0;
        eigen = length / glm::length(v);
        v = next / length;
    }
    // Rounded up by 1e-6 so a caster is never drawn coarser than the error allows.
    return std::sqrt(eigen) * (1.0 + 1e-6);
}

int coarsestLevelWithin(const std::vector<double>& errors, double scale, double allowed) {
    int level = 0;
    for (std::size_t l = 0; l < errors.size(); ++l)
        if (errors[l] * scale <= allowed) level = static_cast<int>(l) + 1;
    return level;
}

} // namespace shadowmap
