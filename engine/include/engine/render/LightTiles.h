#pragma once
// The clustered lit pass's light lists (Frame.h, kMaxClusteredLights): the target cut into
// square tiles of kLightTileSize pixels, each listing, in ascending slot order, the lights
// whose screen footprint (ScreenFootprint.h) touches it. A pixel's loop then visits only the
// lights that can light it: outside its footprint a light's term is exactly zero. No GL.
//
// Tiles, not froxels (tiles cut in depth too): a light's footprint is a rectangle of the
// target, and what a froxel would add is the depth range its light reaches, which a street's
// lamps (each over its own pool, seen side by side) rarely share with another lamp's
// pixels. Measured as the loop's cost in docs/many-lights.md.
#include "engine/scene/ScreenFootprint.h"

#include <cstdint>
#include <span>
#include <vector>

namespace engine {

struct FrameCamera;

struct LightTiles {
    int tileSize = 0;
    int columns = 0, rows = 0;  // tiles per row and per column (the last ones may be cut)
    // Per tile, row by row from the bottom (window coordinates): where its list starts in
    // `lights` and how many lights it holds (lit.frag's uTileRanges: uvec2).
    std::vector<std::uint32_t> ranges;  // 2 per tile: first, count
    std::vector<std::uint32_t> lights;  // every tile's list, one after another
    // The list of the tile holding pixel (x, y) of the target.
    std::span<const std::uint32_t> lightsAt(int x, int y) const;
};

// The lists for footprints[i] = light slot i's footprint on a width x height target.
LightTiles buildLightTiles(std::span<const PixelRect> footprints, int width, int height, int tileSize);

// Every light instance's footprint this frame, by slot: each light against the bounds of the
// meshes the camera may see (lightFootprint), the whole target for a light that reaches
// everything (directional, unranged point).
std::vector<PixelRect> lightFootprints(const Scene& scene, const FrameCamera& camera);

}  // namespace engine
