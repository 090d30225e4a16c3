#include "engine/render/ShadingRegions.h"

#include <algorithm>
#include <stdexcept>

namespace engine {

namespace {

// A row's cells after merging: [x0, x1) with one set of footprints each.
struct Run {
    int x0, x1;
    std::uint32_t footprints;
    bool operator==(const Run&) const = default;
};

// The sorted distinct cut positions in [0, size]: the target's edges and every footprint edge.
std::vector<int> cuts(std::span<const PixelRect> footprints, int size, int PixelRect::*low, int PixelRect::*high) {
    std::vector<int> positions{0, size};
    for (const PixelRect& footprint : footprints)
        if (!footprint.empty()) {
            positions.push_back(std::clamp(footprint.*low, 0, size));
            positions.push_back(std::clamp(footprint.*high, 0, size));
        }
    std::sort(positions.begin(), positions.end());
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
    return positions;
}

}  // namespace

std::vector<ShadingRegion> splitByFootprints(std::span<const PixelRect> footprints, int width, int height) {
    if (footprints.size() > 32) throw std::invalid_argument("splitByFootprints: more than 32 footprints");
    std::vector<ShadingRegion> regions;
    if (width <= 0 || height <= 0) return regions;
    const std::vector<int> xs = cuts(footprints, width, &PixelRect::x0, &PixelRect::x1);
    const std::vector<int> ys = cuts(footprints, height, &PixelRect::y0, &PixelRect::y1);
    std::vector<Run> previousRow;
    std::size_t previousRowFirst = 0;  // the regions previousRow opened
    for (std::size_t row = 0; row + 1 < ys.size(); ++row) {
        std::vector<Run> runs;
        for (std::size_t column = 0; column + 1 < xs.size(); ++column) {
            const PixelRect cell{xs[column], ys[row], xs[column + 1], ys[row + 1]};
            std::uint32_t covering = 0;
            for (std::size_t i = 0; i < footprints.size(); ++i)
                if (footprints[i].intersects(cell)) covering |= 1u << i;  // cells never straddle an edge
            if (!runs.empty() && runs.back().footprints == covering) runs.back().x1 = cell.x1;
            else runs.push_back({cell.x0, cell.x1, covering});
        }
        if (runs == previousRow) {
            for (std::size_t i = previousRowFirst; i < regions.size(); ++i) regions[i].rect.y1 = ys[row + 1];
            continue;
        }
        previousRowFirst = regions.size();
        for (const Run& run : runs) regions.push_back({{run.x0, ys[row], run.x1, ys[row + 1]}, run.footprints});
        previousRow = std::move(runs);
    }
    return regions;
}

}  // namespace engine
