#pragma once
// Axis-aligned bounding box in double precision: world bounds must stay exact far from
// the origin (a scene 10^6 units away must shadow like one at 0).
#include <glm/glm.hpp>
#include <limits>

namespace engine {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    bool operator==(const Aabb&) const = default;
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::dvec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void extend(const Aabb& other) {
        if (!other.empty()) { extend(other.min); extend(other.max); }
    }
    glm::dvec3 center() const { return (min + max) * 0.5; }
    glm::dvec3 extent() const { return max - min; }
    // The eight corners, for transforming and frustum fitting.
    glm::dvec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
    // Bounds of this box after an affine transform (all eight corners, exact for boxes).
    Aabb transformed(const glm::dmat4& m) const {
        Aabb out;
        if (empty()) return out;
        for (int i = 0; i < 8; ++i) out.extend(glm::dvec3(m * glm::dvec4(corner(i), 1.0)));
        return out;
    }
};

} // namespace engine
