#include "LightTileImage.h"

#include <algorithm>

namespace tools {

namespace {

std::array<std::uint8_t, 3> colorOf(std::uint32_t count) {
    if (count == 0) return {0, 0, 0};
    return truth::heatColor(static_cast<double>(count), kLightTileScale);
}

} // namespace

std::vector<std::uint8_t> lightTileImage(std::span<const std::uint32_t> counts, int tileColumns, int tileSize,
                                         int width, int height) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4, 0);
    for (int row = 0; row < height; ++row) {
        const int windowY = height - 1 - row;  // the image's top row is the window's last
        for (int x = 0; x < width; ++x) {
            const std::size_t tile = static_cast<std::size_t>(windowY / tileSize) * tileColumns + x / tileSize;
            const std::array<std::uint8_t, 3> rgb = colorOf(tile < counts.size() ? counts[tile] : 0);
            std::uint8_t* pixel = &rgba[(static_cast<std::size_t>(row) * width + x) * 4];
            std::copy(rgb.begin(), rgb.end(), pixel);
            pixel[3] = 255;
        }
    }
    return rgba;
}

std::string lightTileLegend() {
    std::string legend = "black 0 lights";
    for (const truth::HeatStop& stop : kLightTileScale)
        legend += std::string(", ") + stop.name + " " + std::to_string(static_cast<int>(stop.value));
    return legend + " or more";
}

} // namespace tools
