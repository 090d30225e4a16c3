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

// `plan` for a region outside the footprints of the lights `slots`: their shade is the
// constant 1 (their light adds nothing there), so the region's programs look none of them up.
ShadeCache::Plan withoutLookups(ShadeCache::Plan plan, const std::vector<int>& slots);

// The lights a split may limit under `plan`: evaluated and not stored this frame, and not
// directional (whose footprint is everything the camera sees).
std::vector<int> footprintLimitableLights(const Scene& scene, const ShadeCache::Plan& plan);

} // namespace engine
