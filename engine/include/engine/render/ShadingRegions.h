#pragma once
// The lit pass's split of its target by light footprints (scene/ScreenFootprint.h):
// rectangles, each with the set of footprints that cover it. The lit pass looks a light's
// shadow up only in the regions its footprint covers; in the others the light's term is
// exactly zero whatever its shade, so a constant stands in for the lookup. No GL.
#include "engine/scene/ScreenFootprint.h"

#include <cstdint>
#include <span>
#include <vector>

namespace engine {

struct ShadingRegion {
    PixelRect rect;
    std::uint32_t footprints = 0;  // bit i: footprints[i] covers the whole rect
};

// Cuts the width x height target at every footprint edge into a grid of cells, each covered
// by a set of footprints; cells of a row with equal sets merge left to right, and a row whose
// merged cells repeat the row below merges into it. The regions partition the target: every
// pixel lies in exactly one. At most 32 footprints.
std::vector<ShadingRegion> splitByFootprints(std::span<const PixelRect> footprints, int width, int height);

}  // namespace engine
