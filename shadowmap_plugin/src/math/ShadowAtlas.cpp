#include "math/ShadowAtlas.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadowmap {

namespace {

struct Cell {
    int x = 0, y = 0;
};

bool isPowerOfTwo(std::int64_t v) { return v > 0 && (v & (v - 1)) == 0; }

std::int64_t nextPowerOfTwo(std::int64_t v) {
    std::int64_t p = 1;
    while (p < v) p *= 2;
    return p;
}

std::string describe(const AtlasKey& key) {
    return "light " + std::to_string(key.light) + " layer " + std::to_string(key.layer);
}

// The free aligned blocks of one frame's layout, by level: level 0 is the whole atlas, level
// l has side atlasSize >> l. Rebuilt every frame from the blocks placed in it, so it never
// frees (a left light's space is simply not taken again) and never needs to merge buddies.
// Free blocks are only ever quadrants split off an allocation, so their sides are at least
// the smallest block taken so far: what makes the largest-first re-pack perfect.
class BlockTree {
public:
    explicit BlockTree(int atlasSize) : atlasSize_(atlasSize) {
        int levels = 1;
        for (int side = atlasSize; side > 1; side /= 2) ++levels;
        free_.resize(levels);
        free_[0].insert({0, 0});
    }

    // The smallest free block of `side` or wider, split down to `side`; the lowest (y, x)
    // among equals, so layouts are deterministic.
    std::optional<Cell> takeBestFit(int side) {
        const int target = levelOf(side);
        for (int level = target; level >= 0; --level) {
            if (free_[level].empty()) continue;
            const auto [y, x] = *free_[level].begin();
            free_[level].erase(free_[level].begin());
            splitDown(level, {x, y}, target, {x, y});
            return Cell{x, y};
        }
        return std::nullopt;
    }

    // Takes the aligned block of `side` at `cell` if it is free (false if any of it is taken).
    bool takeAt(Cell cell, int side) {
        const int target = levelOf(side);
        for (int level = target; level >= 0; --level) {
            const int s = sideOf(level);
            const Cell holder{cell.x / s * s, cell.y / s * s};
            auto found = free_[level].find({holder.y, holder.x});
            if (found == free_[level].end()) continue;
            free_[level].erase(found);
            splitDown(level, holder, target, cell);
            return true;
        }
        return false;
    }

    // Every free aligned cell of `side`, lowest (y, x) first.
    std::vector<Cell> freeCells(int side) const {
        std::vector<Cell> cells;
        for (int level = levelOf(side); level >= 0; --level) {
            const int s = sideOf(level);
            for (const auto& [y, x] : free_[level])
                for (int cy = y; cy < y + s; cy += side)
                    for (int cx = x; cx < x + s; cx += side) cells.push_back({cx, cy});
        }
        std::sort(cells.begin(), cells.end(),
                  [](const Cell& a, const Cell& b) { return std::pair(a.y, a.x) < std::pair(b.y, b.x); });
        return cells;
    }

private:
    int sideOf(int level) const { return atlasSize_ >> level; }
    int levelOf(int side) const {
        int level = 0;
        while (sideOf(level) > side) ++level;
        return level;
    }

    // Splits the free block `block` of `level` into quadrants down to `targetLevel`, keeping
    // the quadrant that holds `target` each time and freeing the other three.
    void splitDown(int level, Cell block, int targetLevel, Cell target) {
        for (; level < targetLevel; ++level) {
            const int half = sideOf(level + 1);
            Cell keep = block;
            for (int qy = 0; qy < 2; ++qy)
                for (int qx = 0; qx < 2; ++qx) {
                    const Cell quadrant{block.x + qx * half, block.y + qy * half};
                    const bool holdsTarget = target.x >= quadrant.x && target.x < quadrant.x + half &&
                                             target.y >= quadrant.y && target.y < quadrant.y + half;
                    if (holdsTarget)
                        keep = quadrant;
                    else
                        free_[level + 1].insert({quadrant.y, quadrant.x});
                }
            block = keep;
        }
    }

    int atlasSize_;
    std::vector<std::set<std::pair<int, int>>> free_;  // (y, x) of each free block, by level
};

// One admitted request on its way to a block.
struct Pending {
    AtlasKey key;
    int mapSize = 0;
    int blockSide = 0;
    std::optional<AtlasRect> oldBlock;   // last frame's block, when it had the same side
    std::optional<Cell> cell;            // where it goes this frame
};

// Where the re-pack puts a map that cannot go back to its old block: the free cell that
// covers the least of the old blocks still waiting to be placed (so few of them move),
// lowest (y, x) among equals. Every waiting block is this side or smaller (largest first),
// so each lies inside exactly one cell of this side.
Cell leastDisturbingCell(const BlockTree& tree, int side, std::span<const Pending> waiting) {
    std::map<std::pair<int, int>, std::int64_t> coveredArea;
    for (const Pending& p : waiting)
        if (p.oldBlock)
            coveredArea[{p.oldBlock->y / side * side, p.oldBlock->x / side * side}] +=
                std::int64_t(p.oldBlock->size) * p.oldBlock->size;
    const std::vector<Cell> cells = tree.freeCells(side);
    if (cells.empty()) throw std::logic_error("ShadowAtlas: re-pack found no free block (a bug)");
    const Cell* best = nullptr;
    std::int64_t bestArea = std::numeric_limits<std::int64_t>::max();
    for (const Cell& cell : cells) {
        auto found = coveredArea.find({cell.y, cell.x});
        const std::int64_t area = found == coveredArea.end() ? 0 : found->second;
        if (area < bestArea) best = &cell, bestArea = area;
    }
    return *best;
}

// Lays out every admitted map from an empty atlas, largest first; among equals those that
// had a block of that side first, each back at its old block while it is free.
void repack(int atlasSize, std::vector<Pending>& maps) {
    std::stable_sort(maps.begin(), maps.end(), [](const Pending& a, const Pending& b) {
        if (a.blockSide != b.blockSide) return a.blockSide > b.blockSide;
        return a.oldBlock.has_value() > b.oldBlock.has_value();
    });
    BlockTree tree(atlasSize);
    for (std::size_t i = 0; i < maps.size(); ++i) {
        Pending& map = maps[i];
        if (map.oldBlock && tree.takeAt({map.oldBlock->x, map.oldBlock->y}, map.blockSide)) {
            map.cell = Cell{map.oldBlock->x, map.oldBlock->y};
            continue;
        }
        const Cell cell = leastDisturbingCell(tree, map.blockSide, std::span(maps).subspan(i + 1));
        tree.takeAt(cell, map.blockSide);
        map.cell = cell;
    }
}

// Keeps every map at its old block and puts the others in the smallest free blocks, largest
// first; false if one finds no block (fragmentation: the caller re-packs).
bool placeIncrementally(int atlasSize, std::vector<Pending>& maps) {
    BlockTree tree(atlasSize);
    for (Pending& map : maps) {
        if (!map.oldBlock) continue;
        // Last frame's blocks never overlap, so each is still free here.
        if (!tree.takeAt({map.oldBlock->x, map.oldBlock->y}, map.blockSide))
            throw std::logic_error("ShadowAtlas: last frame's blocks overlap (a bug)");
        map.cell = Cell{map.oldBlock->x, map.oldBlock->y};
    }
    std::vector<Pending*> newcomers;
    for (Pending& map : maps)
        if (!map.oldBlock) newcomers.push_back(&map);
    std::stable_sort(newcomers.begin(), newcomers.end(),
                     [](const Pending* a, const Pending* b) { return a->blockSide > b->blockSide; });
    for (Pending* map : newcomers) {
        map->cell = tree.takeBestFit(map->blockSide);
        if (!map->cell) return false;
    }
    return true;
}

} // namespace

ShadowAtlas::ShadowAtlas(int atlasSize, int border) : atlasSize_(atlasSize), border_(border) {
    if (!isPowerOfTwo(atlasSize))
        throw std::invalid_argument("ShadowAtlas: the atlas side " + std::to_string(atlasSize) +
                                    " is not a power of two");
    if (border < 0) throw std::invalid_argument("ShadowAtlas: negative border " + std::to_string(border));
}

std::int64_t ShadowAtlas::blockSideFor(int mapSize) const {
    return nextPowerOfTwo(std::int64_t(mapSize) + 2 * std::int64_t(border_));
}

const AtlasFrameReport& ShadowAtlas::allocate(const std::vector<AtlasRequest>& requests) {
    // Checked before anything changes, so a refused frame leaves last frame's layout.
    std::set<AtlasKey> requested;
    for (const AtlasRequest& request : requests) {
        if (request.size < 1)
            throw std::invalid_argument("ShadowAtlas: " + describe(request.key) + " asks for a map of " +
                                        std::to_string(request.size) + " texels");
        if (!requested.insert(request.key).second)
            throw std::invalid_argument("ShadowAtlas: " + describe(request.key) + " is requested twice");
    }

    AtlasFrameReport report;
    // Admission by area, in order of importance: what is admitted always fits (the header).
    std::int64_t areaLeft = std::int64_t(atlasSize_) * atlasSize_;
    std::vector<Pending> admitted;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        const AtlasRequest& request = requests[i];
        const std::int64_t side = blockSideFor(request.size);
        if (side > atlasSize_ || side * side > areaLeft) {
            report.unplaced.push_back(request.key);
            continue;
        }
        areaLeft -= side * side;
        Pending map{request.key, request.size, int(side), std::nullopt, std::nullopt};
        auto old = placements_.find(request.key);
        if (old != placements_.end() && old->second.block.size == side) map.oldBlock = old->second.block;
        admitted.push_back(map);
    }

    if (!placeIncrementally(atlasSize_, admitted)) {
        for (Pending& map : admitted) map.cell.reset();
        repack(atlasSize_, admitted);
        report.repacked = true;
    }

    std::map<AtlasKey, AtlasPlacement> placements;
    for (const Pending& map : admitted) {
        const AtlasRect block{map.cell->x, map.cell->y, map.blockSide};
        const AtlasRect inner{block.x + border_, block.y + border_, map.mapSize};
        placements[map.key] = {block, inner};
        auto old = placements_.find(map.key);
        const bool contentsKept = map.oldBlock && old->second.map.size == map.mapSize;
        if (!contentsKept)
            report.placed.push_back(map.key);
        else if (!(block == *map.oldBlock))
            report.moved.push_back(map.key);
    }
    for (const auto& [key, placement] : placements_)
        if (!requested.count(key)) report.freed.push_back(key);
    std::sort(report.placed.begin(), report.placed.end());
    std::sort(report.moved.begin(), report.moved.end());
    std::sort(report.unplaced.begin(), report.unplaced.end());

    placements_ = std::move(placements);
    report_ = std::move(report);
    return report_;
}

std::optional<AtlasPlacement> ShadowAtlas::find(const AtlasKey& key) const {
    auto found = placements_.find(key);
    if (found == placements_.end()) return std::nullopt;
    return found->second;
}

double ShadowAtlas::occupancy() const {
    std::int64_t texels = 0;
    for (const auto& [key, placement] : placements_) texels += std::int64_t(placement.map.size) * placement.map.size;
    return double(texels) / (double(atlasSize_) * atlasSize_);
}

double ShadowAtlas::blockOccupancy() const {
    std::int64_t texels = 0;
    for (const auto& [key, placement] : placements_)
        texels += std::int64_t(placement.block.size) * placement.block.size;
    return double(texels) / (double(atlasSize_) * atlasSize_);
}

int ShadowAtlas::changedCount() const { return int(report_.placed.size() + report_.moved.size()); }

} // namespace shadowmap
