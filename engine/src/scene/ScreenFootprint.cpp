#include "engine/scene/ScreenFootprint.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace engine {

namespace {

// Relative growth of a lit volume (range, cone length) and its cone angle: float rounding in
// the shader's distance and angle is ~1e-7 relative, so these margins are generous and cost
// under a pixel at any sensible distance.
constexpr double kVolumeMargin = 1e-3;
constexpr double kConeAngleMargin = 1e-3;
// Past this half angle the pyramid around a cone grows without bound (tan -> infinity).
constexpr double kWidestBoundedCone = 1.55;  // radians, about 89 degrees

double nearPlaneDistance(const glm::dvec4& clip) { return clip.z + clip.w; }

// Two unit vectors perpendicular to unit `axis` and to each other.
void perpendicularBasis(const glm::dvec3& axis, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(axis, helper));
    v = glm::cross(axis, u);
}

// A convex polyhedron as its faces, each a convex polygon (corners in order).
struct ConvexPolyhedron {
    std::vector<std::vector<glm::dvec3>> faces;
};

// The part of `solid` where dot(normal, x) + offset >= 0: each face clipped by the plane
// (Sutherland-Hodgman), and the cut closed by a face through the crossings, ordered by angle
// around their centre.
ConvexPolyhedron clipByPlane(const ConvexPolyhedron& solid, const glm::dvec3& normal, double offset) {
    ConvexPolyhedron clipped;
    std::vector<glm::dvec3> cut;
    for (const std::vector<glm::dvec3>& face : solid.faces) {
        std::vector<glm::dvec3> kept;
        for (std::size_t i = 0; i < face.size(); ++i) {
            const glm::dvec3& from = face[i];
            const glm::dvec3& to = face[(i + 1) % face.size()];
            const double a = glm::dot(normal, from) + offset, b = glm::dot(normal, to) + offset;
            if (a >= 0.0) kept.push_back(from);
            if ((a >= 0.0) != (b >= 0.0)) {
                const glm::dvec3 crossing = from + (to - from) * (a / (a - b));
                kept.push_back(crossing);
                cut.push_back(crossing);
            }
        }
        if (kept.size() >= 3) clipped.faces.push_back(std::move(kept));
    }
    if (cut.size() >= 3) {
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& point : cut) centre += point;
        centre /= double(cut.size());
        glm::dvec3 u, v;
        perpendicularBasis(glm::normalize(normal), u, v);
        std::sort(cut.begin(), cut.end(), [&](const glm::dvec3& p, const glm::dvec3& q) {
            return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
                   std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
        });
        clipped.faces.push_back(std::move(cut));
    }
    return clipped;
}

// The corners of `solid` inside `box` (none if they do not meet).
std::vector<glm::dvec3> clipToBox(ConvexPolyhedron solid, const Aabb& box) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 normal(0.0);
        normal[axis] = 1.0;
        solid = clipByPlane(solid, normal, -box.min[axis]);
        solid = clipByPlane(solid, -normal, box.max[axis]);
    }
    std::vector<glm::dvec3> corners;
    for (const std::vector<glm::dvec3>& face : solid.faces) corners.insert(corners.end(), face.begin(), face.end());
    return corners;
}

}  // namespace

PixelRect projectedFootprint(const glm::dmat4& viewProjection, std::span<const glm::dvec3> points, int width,
                             int height) {
    std::vector<glm::dvec4> clip;
    clip.reserve(points.size());
    for (const glm::dvec3& point : points) clip.push_back(viewProjection * glm::dvec4(point, 1.0));
    // The clipped hull's corners are among the points in front of the near plane and the
    // plane's crossings of segments between a point in front and one behind. Every pair, not
    // only the hull's edges: the extra crossings lie inside the clipped hull, so the bounds
    // stay exact.
    std::vector<glm::dvec4> kept;
    for (const glm::dvec4& point : clip)
        if (nearPlaneDistance(point) >= 0.0) kept.push_back(point);
    for (const glm::dvec4& front : clip) {
        if (nearPlaneDistance(front) < 0.0) continue;
        for (const glm::dvec4& behind : clip) {
            if (nearPlaneDistance(behind) >= 0.0) continue;
            const double t = nearPlaneDistance(front) / (nearPlaneDistance(front) - nearPlaneDistance(behind));
            kept.push_back(front + t * (behind - front));
        }
    }
    if (kept.empty()) return {};
    const PixelRect whole = PixelRect::target(width, height);
    glm::dvec2 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const glm::dvec4& point : kept) {
        if (!(point.w > 0.0)) return whole;
        const glm::dvec2 window = (glm::dvec2(point) / point.w * 0.5 + 0.5) * glm::dvec2(width, height);
        low = glm::min(low, window);
        high = glm::max(high, window);
    }
    if (!std::isfinite(low.x) || !std::isfinite(low.y) || !std::isfinite(high.x) || !std::isfinite(high.y))
        return whole;
    // Huge window coordinates (a point barely in front of the eye) clamp to the target: as
    // doubles, before the conversion to int.
    const auto clampTo = [](double value, int size) { return static_cast<int>(std::clamp(value, 0.0, double(size))); };
    return {clampTo(std::floor(low.x) - 1.0, width), clampTo(std::floor(low.y) - 1.0, height),
            clampTo(std::ceil(high.x) + 1.0, width), clampTo(std::ceil(high.y) + 1.0, height)};
}

PixelRect projectedFootprint(const glm::dmat4& viewProjection, const Aabb& box, int width, int height) {
    if (box.empty()) return {};
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) corners[i] = box.corner(i);
    return projectedFootprint(viewProjection, corners, width, height);
}

PixelRect enclosing(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PixelRect intersection(const PixelRect& a, const PixelRect& b) {
    const PixelRect both{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
    return both.empty() ? PixelRect{} : both;
}

PixelRect lightFootprint(const Light& light, const LightInstance& placed, std::span<const Aabb> receivers,
                         const glm::dmat4& viewProjection, int width, int height) {
    const PixelRect whole = PixelRect::target(width, height);
    const glm::dvec3 position = placed.position();
    PixelRect footprint;
    switch (light.type) {
    case Light::Type::Directional: return receivers.empty() ? footprint : whole;
    case Light::Type::Point: {
        if (!(light.range > 0.0)) return receivers.empty() ? footprint : whole;
        const glm::dvec3 reach(light.range * (1.0 + kVolumeMargin));
        for (const Aabb& receiver : receivers) {
            const Aabb lit{glm::max(receiver.min, position - reach), glm::min(receiver.max, position + reach)};
            footprint = enclosing(footprint, projectedFootprint(viewProjection, lit, width, height));
        }
        return footprint;
    }
    case Light::Type::Spot: {
        const double halfAngle = light.outerConeAngle + kConeAngleMargin;
        if (!(halfAngle < kWidestBoundedCone)) return receivers.empty() ? footprint : whole;
        const glm::dvec3 axis = placed.direction();
        glm::dvec3 u, v;
        perpendicularBasis(axis, u, v);
        for (const Aabb& receiver : receivers) {
            if (receiver.empty()) continue;
            // The cone lights nothing of this box farther than its farthest corner.
            double length = 0.0;
            for (int i = 0; i < 8; ++i) length = std::max(length, glm::length(receiver.corner(i) - position));
            if (light.range > 0.0) length = std::min(length, light.range);
            length *= 1.0 + kVolumeMargin;
            // A square pyramid around the cone: apex a little behind the light, base at
            // `length` along the axis with half side length * tan(half angle). Whatever the
            // apex's offset, the pyramid's cross-section holds the cone's at every distance
            // up to `length`.
            const double halfSide = length * std::tan(halfAngle);
            const glm::dvec3 apex = position - axis * (length * kVolumeMargin);
            const glm::dvec3 base = position + axis * length;
            const std::array<glm::dvec3, 4> corners = {base + (u + v) * halfSide, base + (u - v) * halfSide,
                                                       base - (u + v) * halfSide, base - (u - v) * halfSide};
            ConvexPolyhedron pyramid{{{corners[0], corners[1], corners[2], corners[3]},
                                      {apex, corners[1], corners[0]},
                                      {apex, corners[2], corners[1]},
                                      {apex, corners[3], corners[2]},
                                      {apex, corners[0], corners[3]}}};
            const std::vector<glm::dvec3> inside = clipToBox(std::move(pyramid), receiver);
            if (!inside.empty())
                footprint = enclosing(footprint, projectedFootprint(viewProjection, inside, width, height));
        }
        return footprint;
    }
    }
    return whole;
}

}  // namespace engine
