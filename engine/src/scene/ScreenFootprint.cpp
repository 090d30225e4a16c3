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
        // Each angle once (atan2 inside the comparison was most of a footprint's time).
        std::vector<std::pair<double, glm::dvec3>> around;
        around.reserve(cut.size());
        for (const glm::dvec3& point : cut)
            around.emplace_back(std::atan2(glm::dot(point - centre, v), glm::dot(point - centre, u)), point);
        std::sort(around.begin(), around.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 0; i < around.size(); ++i) cut[i] = around[i].second;
        clipped.faces.push_back(std::move(cut));
    }
    return clipped;
}

// The corners of `solid` (whose corners `solidBounds` bounds) inside `box`; none if they do
// not meet. Only the box's faces that cut the solid's bounds clip: most receivers of a
// light lie wholly outside its cone's bounds or hold it whole along some axis.
std::vector<glm::dvec3> clipToBox(ConvexPolyhedron solid, const Aabb& solidBounds, const Aabb& box) {
    for (int axis = 0; axis < 3; ++axis)
        if (solidBounds.max[axis] < box.min[axis] || solidBounds.min[axis] > box.max[axis]) return {};
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 normal(0.0);
        normal[axis] = 1.0;
        if (solidBounds.min[axis] < box.min[axis]) solid = clipByPlane(solid, normal, -box.min[axis]);
        if (solidBounds.max[axis] > box.max[axis]) solid = clipByPlane(solid, -normal, box.max[axis]);
    }
    std::vector<glm::dvec3> corners;
    for (const std::vector<glm::dvec3>& face : solid.faces) corners.insert(corners.end(), face.begin(), face.end());
    return corners;
}

Aabb intersectionOf(const Aabb& a, const Aabb& b) { return Aabb{glm::max(a.min, b.min), glm::min(a.max, b.max)}; }

// A spot light's cone held in a square pyramid cut at some length, and the pyramid's bounds.
struct Cone {
    ConvexPolyhedron pyramid;
    Aabb bounds;
    glm::dvec3 interior;  // the corners' centroid: inside, as the pyramid is convex (the
                          // centre of its bounds need not be)

    // How `box` lies against the pyramid, by its faces' planes: wholly outside one (the cheap
    // test that spares most receivers of a narrow cone the clip), wholly inside all (the
    // clip would return the box: most receivers of a key light), or cut.
    enum class Overlap { Outside, Inside, Cut };
    Overlap overlap(const Aabb& box) const {
        bool inside = true;
        for (const std::vector<glm::dvec3>& face : pyramid.faces) {
            glm::dvec3 outward = glm::cross(face[1] - face[0], face[2] - face[0]);
            if (glm::dot(outward, interior - face[0]) > 0.0) outward = -outward;
            int outsideCorners = 0;
            for (int i = 0; i < 8; ++i) outsideCorners += glm::dot(outward, box.corner(i) - face[0]) > 0.0;
            if (outsideCorners == 8) return Overlap::Outside;
            inside = inside && outsideCorners == 0;
        }
        return inside ? Overlap::Inside : Overlap::Cut;
    }
};

// The pyramids around one spot light's cone: apex a little behind the light, base at
// `length` along the axis with half side length * tan(half angle). Whatever the apex's
// offset, a pyramid's cross-section holds the cone's at every distance up to `length`.
class ConePyramids {
public:
    ConePyramids(const LightInstance& placed, double halfAngle)
        : position_(placed.position()), axis_(placed.direction()), tangent_(std::tan(halfAngle)) {
        perpendicularBasis(axis_, u_, v_);
    }
    // How far the cone can light `box`: to its farthest corner, at most `range` (0: no
    // limit), with the margin.
    double reach(const Aabb& box, double range) const {
        double length = 0.0;
        for (int i = 0; i < 8; ++i) length = std::max(length, glm::length(box.corner(i) - position_));
        if (range > 0.0) length = std::min(length, range);
        return length * (1.0 + kVolumeMargin);
    }
    Cone cutAt(double length) const {
        const double halfSide = length * tangent_;
        const glm::dvec3 apex = position_ - axis_ * (length * kVolumeMargin);
        const glm::dvec3 base = position_ + axis_ * length;
        const std::array<glm::dvec3, 4> corners = {base + (u_ + v_) * halfSide, base + (u_ - v_) * halfSide,
                                                   base - (u_ + v_) * halfSide, base - (u_ - v_) * halfSide};
        Cone cone{{{{corners[0], corners[1], corners[2], corners[3]},
                    {apex, corners[1], corners[0]},
                    {apex, corners[2], corners[1]},
                    {apex, corners[3], corners[2]},
                    {apex, corners[0], corners[3]}}},
                  {},
                  (apex + corners[0] + corners[1] + corners[2] + corners[3]) / 5.0};
        cone.bounds.extend(apex);
        for (const glm::dvec3& corner : corners) cone.bounds.extend(corner);
        return cone;
    }

private:
    glm::dvec3 position_, axis_, u_, v_;
    double tangent_;
};

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
            const Aabb lit = intersectionOf(receiver, Aabb{position - reach, position + reach});
            footprint = enclosing(footprint, projectedFootprint(viewProjection, lit, width, height));
        }
        return footprint;
    }
    case Light::Type::Spot: {
        const double halfAngle = light.outerConeAngle + kConeAngleMargin;
        if (!(halfAngle < kWidestBoundedCone)) return receivers.empty() ? footprint : whole;
        const ConePyramids cone(placed, halfAngle);
        for (const Aabb& receiver : receivers) {
            if (receiver.empty()) continue;
            const Cone cut = cone.cutAt(cone.reach(receiver, light.range));
            const Cone::Overlap overlap = cut.overlap(receiver);
            if (overlap == Cone::Overlap::Outside) continue;
            if (overlap == Cone::Overlap::Inside) {
                footprint = enclosing(footprint, projectedFootprint(viewProjection, receiver, width, height));
                continue;
            }
            // The box's part inside the pyramid's bounds holds the exact part: when the
            // footprint so far already holds its pixels, the exact clip cannot add any.
            const Aabb roughlyLit = intersectionOf(cut.bounds, receiver);
            if (roughlyLit.empty()) continue;
            if (enclosing(footprint, projectedFootprint(viewProjection, roughlyLit, width, height)) == footprint) continue;
            const std::vector<glm::dvec3> inside = clipToBox(cut.pyramid, cut.bounds, receiver);
            if (!inside.empty())
                footprint = enclosing(footprint, projectedFootprint(viewProjection, inside, width, height));
        }
        return footprint;
    }
    }
    return whole;
}

}  // namespace engine
