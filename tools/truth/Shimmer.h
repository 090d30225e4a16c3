#pragma once
// Shimmer (docs/metrics.md): on a camera path, how often a surface point's shadow state in
// the engine's mask changes from one frame to the next while the truth there stays. Exact
// shadows score 0; a shadow map whose texels move with the camera (a map fitted to the view)
// makes its edges crawl and scores more.
//
// A pixel p of frame a is compared with the pixel q of frame b that sees the same surface
// point: p's world point (SurfaceCapture) projected through b's camera must land within
// kShimmerReprojection pixels of q's centre, on the same mesh instance, and q's own world point
// must lie within one pixel footprint of it (nothing in front). Both pixels must be in their
// frame's evaluation set with the same truth; then the masks' states (lit >= 128) are
// compared. The tight reprojection keeps the two samples at nearly one point, so an edge of
// a perfectly still mask changes state only where it passes within that distance.
#include "truth/SurfaceCapture.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace truth {

// The largest distance, in pixels of frame b, from a reprojected point to the centre of the
// pixel it is compared with.
inline constexpr double kShimmerReprojection = 0.1;

struct ShimmerFrame {
    const SurfaceBuffer* surfaces = nullptr;  // what the camera saw (its camera included)
    std::span<const std::uint8_t> mask;       // the light's shadow mask: 255 lit, 0 shadowed
    std::span<const std::uint8_t> truth;      // RayTracedVisibility::visibility: 1 lit, 0 shadowed
    std::span<const std::uint8_t> evaluated;  // evaluationSet: 1 = in E
};

struct ShimmerCount {
    std::size_t compared = 0;  // pixel pairs that see one point with one truth
    std::size_t changed = 0;   // of those, the mask's state differs
    double fraction() const { return compared ? double(changed) / double(compared) : 0.0; }
    ShimmerCount& operator+=(const ShimmerCount& other) {
        compared += other.compared;
        changed += other.changed;
        return *this;
    }
};

// The pairs between frame a and the next frame b.
ShimmerCount shimmerBetween(const ShimmerFrame& a, const ShimmerFrame& b);

} // namespace truth
