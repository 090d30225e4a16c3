#pragma once
// Where on screen something can show: the pixels a convex volume (a light's lit volume, a
// mesh's bounds) covers under a camera, as a rectangle of the target. The lit pass looks a
// light's shadow up only inside that light's footprint (LitPass.cpp): elsewhere the light's
// term is exactly zero, whatever its shade. No GL.
#include "engine/scene/Aabb.h"
#include "engine/scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace engine {

// Pixels [x0, x1) x [y0, y1) of a target, in window coordinates (origin at the bottom left,
// as glScissor and gl_FragCoord count).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    bool operator==(const PixelRect&) const = default;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    std::int64_t area() const { return empty() ? 0 : std::int64_t(x1 - x0) * (y1 - y0); }
    bool intersects(const PixelRect& other) const {
        return !empty() && !other.empty() && x0 < other.x1 && other.x0 < x1 && y0 < other.y1 && other.y0 < y1;
    }
    static PixelRect target(int width, int height) { return {0, 0, width, height}; }
};

// The pixels whose centres can show a point of the convex hull of `points` on a
// width x height target seen through `viewProjection` (OpenGL clip space): the hull
// clipped to the near plane (z >= -w), projected, widened by one pixel on every side (the
// fragment's interpolated position is the pixel centre's point only up to float rounding)
// and clamped to the target. Empty when the whole hull lies behind the near plane; the whole
// target when a clipped point projects to infinity (w <= 0 on the near plane: not a
// perspective or orthographic camera).
PixelRect projectedFootprint(const glm::dmat4& viewProjection, std::span<const glm::dvec3> points, int width,
                             int height);

// projectedFootprint of a box's eight corners; empty for an empty box.
PixelRect projectedFootprint(const glm::dmat4& viewProjection, const Aabb& box, int width, int height);

// The pixels where `light`, placed by `placed`, can light a point of a surface inside one of
// `receivers` (the bounds of every mesh the lit pass draws): the union, over the receivers,
// of the part of each box inside the light's volume: a spot light's cone, cut at its range
// or at the box's farthest corner, or a point light's range sphere, each held in a pyramid
// or box made a little larger (1e-3 of its size, 1e-3 rad) so float rounding in the shader
// cannot light a pixel outside. The whole target for directional lights, unranged point
// lights and cones of 89 degrees or more (no bounded pyramid holds them).
PixelRect lightFootprint(const Light& light, const LightInstance& placed, std::span<const Aabb> receivers,
                         const glm::dmat4& viewProjection, int width, int height);

// The smallest rect holding both (an empty one holds nothing), and the pixels in both.
PixelRect enclosing(const PixelRect& a, const PixelRect& b);
PixelRect intersection(const PixelRect& a, const PixelRect& b);

}  // namespace engine
