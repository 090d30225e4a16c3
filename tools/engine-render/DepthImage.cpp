#include "DepthImage.h"

#include <algorithm>
#include <limits>

std::vector<std::uint8_t> depthToGray(const engine::DepthReadback& map, int& width, int& height) {
    width = map.width * map.layers;
    height = map.height;
    float nearest = std::numeric_limits<float>::max(), farthest = 0.0f;
    for (float depth : map.depth)
        if (depth < 1.0f) {
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
        }
    const float range = std::max(farthest - nearest, 1e-12f);
    std::vector<std::uint8_t> gray(static_cast<std::size_t>(width) * height);
    for (int layer = 0; layer < map.layers; ++layer)
        for (int y = 0; y < map.height; ++y)
            for (int x = 0; x < map.width; ++x) {
                const float depth =
                    map.depth[(static_cast<std::size_t>(layer) * map.height + y) * map.width + x];
                gray[static_cast<std::size_t>(y) * width + layer * map.width + x] =
                    depth >= 1.0f ? 255
                                  : static_cast<std::uint8_t>(230.0f * (depth - nearest) / range + 0.5f);
            }
    return gray;
}
