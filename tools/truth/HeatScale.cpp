#include "truth/HeatScale.h"

#include <cmath>

namespace truth {

std::array<std::uint8_t, 3> heatColor(double value, std::span<const HeatStop> scale) {
    if (value <= scale.front().value) return scale.front().rgb;
    for (std::size_t i = 1; i < scale.size(); ++i) {
        const HeatStop &low = scale[i - 1], &high = scale[i];
        if (value > high.value) continue;
        const double t = std::log2(value / low.value) / std::log2(high.value / low.value);
        std::array<std::uint8_t, 3> out{};
        for (int c = 0; c < 3; ++c)
            out[c] = static_cast<std::uint8_t>(std::lround(low.rgb[c] + t * (high.rgb[c] - low.rgb[c])));
        return out;
    }
    return scale.back().rgb;
}

} // namespace truth
