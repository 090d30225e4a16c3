#pragma once
// The shadow atlas's allocator, for scenes with many shadowed lights: where in one square depth
// texture of `atlasSize` texels per side each map lives (a spot's map, a cube face, a
// cascade: one request each). No GL: the plugin renders into and reads from the rectangles
// it hands out.
//
// Each frame the caller lists this frame's maps (allocate()). A map requested again with the
// same block keeps its rectangle, so its cached contents stay valid; a map no longer
// requested frees its space; new and resized maps go into free space. When they do not fit
// there, everything is re-packed (the report names the maps that moved: their contents are
// lost), and when the atlas is too small even for that, the report names the maps left out
// (the caller shrinks them and asks again). Rectangles never overlap and never leave the
// atlas.
//
// Layout: a buddy quadtree over power-of-two blocks. Each map, with its border, takes one
// aligned square block whose side is the next power of two of (size + 2 * border); a block
// splits into four quadrants, and four free quadrants merge back. Chosen over a skyline
// packer because:
//  - freeing is exact: a leaving light's block is at once reusable by any map as large or
//    smaller, so still lights keep their places while others come and go (a skyline cannot
//    reuse the holes under its line without degenerating into frequent re-packs);
//  - re-packing is perfect: power-of-two blocks placed largest first, each into any free
//    aligned block of its side, always fit when their areas sum to at most the atlas's (the
//    blocks placed so far tile a grid of the current side, so free area means a free cell).
//    Whether a frame's maps fit is therefore known from areas alone, the maps left out are
//    exactly those beyond the area, and the caller knows how much to shrink.
// The cost is the rounding up. A map whose side is a power of two needs a block twice as wide
// once any border is added (1024 + 2 * 33 -> 2048), so the map fills a quarter of its block:
// 16 maps of 1024 in an 8192 atlas instead of 64. A map sized to its block wastes only the
// border: largestMapInBlock(1024) = 958 texels, 87% of the block (4030 in 4096: 97%; 62 in
// 128: 23%). The resolution picker should therefore ask for largestMapInBlock sizes: the
// texel-per-pixel metric it sizes by is continuous, nothing needs a power-of-two map.
//
// Borders: every block keeps `border` texels on each side of its map, so a map's texels are
// at least 2 * border from any other map's. kAtlasBorderTexels is the widest reach of any
// lookup around the point it shades: pcss, PcssLookup::reachTexels = kMaxRadiusTexels (32,
// its blocker search and filter radius) + 1 for its 2x2 comparisons' far texel. Wide pcf
// reaches kMaxFilterRadius (16) + 1 = 17, less. This holds only if the lookup clamps the
// point it shades (after normal offset) into its map's rectangle before the taps, as every
// lookup into a shared atlas must. Mipmapped moments (moments_mipmaps) read the whole map at coarse levels and
// cannot share an atlas with any border.
#include <compare>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace shadowmap {

// PcssLookup::kMaxRadiusTexels + 1 (the header's "Borders"; a unit test keeps them in step).
inline constexpr int kAtlasBorderTexels = 33;

// A map's stable name across frames: the light's slot and the layer of its map (cube face,
// cascade; 0 for a single map).
struct AtlasKey {
    int light = 0;
    int layer = 0;
    auto operator<=>(const AtlasKey&) const = default;
};

// A map wanted this frame, `size` texels per side of the usable map (>= 1, any integer).
struct AtlasRequest {
    AtlasKey key;
    int size = 0;
};

// A square of the atlas in texels: x, y of its lowest corner, `size` texels per side.
struct AtlasRect {
    int x = 0, y = 0, size = 0;
    bool operator==(const AtlasRect&) const = default;
};

// Where a map lives: its block (border included, what the allocator reserves) and the
// usable map inside it (the viewport to render, the rectangle lookups clamp to), `border`
// texels in from the block's lowest corner.
struct AtlasPlacement {
    AtlasRect block;
    AtlasRect map;
};

// What allocate() did, keys in ascending order in each list.
struct AtlasFrameReport {
    std::vector<AtlasKey> placed;    // new, resized, or left out before: render from scratch
    std::vector<AtlasKey> moved;     // same size as before but moved by the re-pack: contents lost
    std::vector<AtlasKey> unplaced;  // beyond the atlas's area (placed before or not): shrink, ask again
    std::vector<AtlasKey> freed;     // placed before, not requested now
    bool repacked = false;           // everything was laid out again this frame
};

class ShadowAtlas {
public:
    // atlasSize: a power of two, texels per side; border >= 0 texels on each side of a map.
    // Throws std::invalid_argument otherwise.
    explicit ShadowAtlas(int atlasSize, int border = kAtlasBorderTexels);

    // Lays out this frame's maps. `requests` come in order of importance: when their blocks'
    // area exceeds the atlas's, each is admitted while the area left holds its block and the
    // rest are reported unplaced (a small map after a large one left out may still fit).
    // Admitted maps always fit: kept maps stay, new ones take free space (the smallest free
    // block that holds them), and when fragmentation leaves no such block everything is
    // re-packed, largest first, each map back at its old block where that is still free.
    // Throws std::invalid_argument on a size < 1 or a key listed twice (nothing changes).
    // Cost: the layout is rebuilt from the kept blocks each frame, O(n log n) for n maps; a
    // re-pack adds, per map it cannot put back, a scan of the free cells of its side.
    const AtlasFrameReport& allocate(const std::vector<AtlasRequest>& requests);

    // The rectangle of a key placed by the last allocate(); nullopt if it is not placed.
    std::optional<AtlasPlacement> find(const AtlasKey& key) const;
    const std::map<AtlasKey, AtlasPlacement>& placements() const { return placements_; }
    const AtlasFrameReport& lastFrame() const { return report_; }

    // Usable map texels / atlas texels: what the maps hold.
    double occupancy() const;
    // Block texels / atlas texels: what is reserved (maps, borders and rounding up).
    double blockOccupancy() const;
    // Maps whose contents must be rendered this frame because of the layout: placed + moved.
    int changedCount() const;

    int atlasSize() const { return atlasSize_; }
    int border() const { return border_; }
    // The block a map of `mapSize` texels takes: the next power of two of mapSize + 2 border.
    std::int64_t blockSideFor(int mapSize) const;
    // The widest map a block of `blockSide` (a power of two) holds; < 1 if none fits.
    int largestMapInBlock(int blockSide) const { return blockSide - 2 * border_; }

private:
    int atlasSize_;
    int border_;
    std::map<AtlasKey, AtlasPlacement> placements_;
    AtlasFrameReport report_;
};

} // namespace shadowmap
