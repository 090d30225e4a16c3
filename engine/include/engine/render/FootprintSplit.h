#pragma once
// Splitting the shaded image by light footprints: where a light can light none of the
// visible meshes, its shade is the constant 1 and needs no lookup. The target is cut into
// rectangles (ShadingRegions.h), each drawn with programs that look up only the lights
// whose footprint covers it, when the lookups that spares outweigh the triangles drawn once
// more per extra region a mesh touches.
#include "engine/render/Frame.h"
#include "engine/render/ShadeCache.h"
#include "engine/scene/ScreenFootprint.h"

#include <utility>
#include <vector>

namespace engine {

struct FootprintSplit {
    // Each region and the shade plan it is drawn with; one region, the whole target, with
    // the frame's plan when no light is worth limiting.
    std::vector<std::pair<PixelRect, ShadeCache::Plan>> regions;
    std::vector<int> limitedLights;  // by slot, ascending
};

FootprintSplit splitByLightFootprints(const Frame& frame, const ShadeCache::Plan& plan);

} // namespace engine
