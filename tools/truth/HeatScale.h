#pragma once
// A heat map's colour scale: stops at values, colours interpolated linearly in log2(value)
// between them (a value twice as large moves the colour as far at any size), clamped beyond
// the first and last. Shared by the texel-density picture (TexelDensityImage.h) and
// engine-render's light-tile picture. Pure CPU.
#include <array>
#include <cstdint>
#include <span>

namespace truth {

struct HeatStop {
    double value;  // > 0
    std::array<std::uint8_t, 3> rgb;
    const char* name;  // for the legend
};

// The colour of a positive finite value on `scale` (stops in ascending order).
std::array<std::uint8_t, 3> heatColor(double value, std::span<const HeatStop> scale);

} // namespace truth
