#include "engine/render/LightTiles.h"

#include "engine/render/Frame.h"
#include "engine/scene/FrustumCull.h"
#include "engine/scene/Scene.h"

#include <algorithm>
#include <stdexcept>

namespace engine {

std::span<const std::uint32_t> LightTiles::lightsAt(int x, int y) const {
    const std::size_t tile = static_cast<std::size_t>(y / tileSize) * columns + x / tileSize;
    return std::span<const std::uint32_t>(lights).subspan(ranges[2 * tile], ranges[2 * tile + 1]);
}

LightTiles buildLightTiles(std::span<const PixelRect> footprints, int width, int height, int tileSize) {
    if (tileSize <= 0) throw std::invalid_argument("buildLightTiles: tile size must be positive");
    LightTiles tiles;
    tiles.tileSize = tileSize;
    tiles.columns = std::max(0, (width + tileSize - 1) / tileSize);
    tiles.rows = std::max(0, (height + tileSize - 1) / tileSize);
    const std::size_t tileCount = static_cast<std::size_t>(tiles.columns) * tiles.rows;
    // Two passes over the footprints: count per tile, then place each slot at its tile's next
    // free entry. Slots are visited in order, so every list comes out ascending.
    std::vector<std::uint32_t> counts(tileCount, 0);
    auto forEachTile = [&](const PixelRect& footprint, auto&& visit) {
        const PixelRect clipped = intersection(footprint, PixelRect::target(width, height));
        if (clipped.empty()) return;
        for (int row = clipped.y0 / tileSize; row <= (clipped.y1 - 1) / tileSize; ++row)
            for (int column = clipped.x0 / tileSize; column <= (clipped.x1 - 1) / tileSize; ++column)
                visit(static_cast<std::size_t>(row) * tiles.columns + column);
    };
    for (const PixelRect& footprint : footprints) forEachTile(footprint, [&](std::size_t tile) { ++counts[tile]; });
    tiles.ranges.resize(2 * tileCount);
    std::uint32_t first = 0;
    for (std::size_t tile = 0; tile < tileCount; ++tile) {
        tiles.ranges[2 * tile] = first;
        first += counts[tile];
    }
    tiles.lights.resize(first);
    std::vector<std::uint32_t> next(tileCount, 0);
    for (std::size_t slot = 0; slot < footprints.size(); ++slot)
        forEachTile(footprints[slot], [&](std::size_t tile) {
            tiles.lights[tiles.ranges[2 * tile] + next[tile]++] = static_cast<std::uint32_t>(slot);
        });
    for (std::size_t tile = 0; tile < tileCount; ++tile) tiles.ranges[2 * tile + 1] = counts[tile];
    return tiles;
}

std::vector<PixelRect> lightFootprints(const Scene& scene, const FrameCamera& camera) {
    const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    std::vector<Aabb> visible;
    for (const MeshInstance& instance : scene.meshInstances)
        if (boxIntersectsFrustum(viewProjection, instance.worldBounds)) visible.push_back(instance.worldBounds);
    std::vector<PixelRect> footprints;
    footprints.reserve(scene.lightInstances.size());
    for (const LightInstance& placed : scene.lightInstances)
        footprints.push_back(
            lightFootprint(scene.lights[placed.light], placed, visible, viewProjection, camera.width, camera.height));
    return footprints;
}

}  // namespace engine
