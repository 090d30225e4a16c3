#pragma once
// engine-render --light-tiles: the clustered lit pass's tile lists as a heat map, each pixel
// coloured by how many lights its tile's list holds (engine/render/LightTiles.h): what the
// pixel's loop visits. Pure CPU.
#include "truth/HeatScale.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tools {

// The scale (truth/HeatScale.h: log2 interpolation); no light at all is black.
inline constexpr std::array<truth::HeatStop, 4> kLightTileScale = {{
    {1.0, {0, 0, 255}, "blue"},
    {4.0, {0, 255, 0}, "green"},
    {16.0, {255, 255, 0}, "yellow"},
    {64.0, {255, 0, 0}, "red"},
}};

// RGBA8, top row first, width x height pixels, from `counts` (tileColumns x tileRows tiles
// of tileSize pixels, bottom row first).
std::vector<std::uint8_t> lightTileImage(std::span<const std::uint32_t> counts, int tileColumns, int tileSize,
                                         int width, int height);

// "black 0 lights, blue 1, green 4, yellow 16, red 64 or more".
std::string lightTileLegend();

} // namespace tools
