#pragma once
// Automatic bias: per light, the polygon offset (factor, units) that minimizes acne + leak
// against the truth over the views, for the setting the search found best among those that
// draw with an offset. A descent on a lattice: from the variant's default offset, each round
// measures the four lattice neighbours (factor or units one step up or down) of every light
// at once and moves to the best if it lowers the error; a light stops when none does.
#include "Search.h"

#include <array>
#include <optional>
#include <vector>

namespace shadowmap_tune {

// Factors multiply the depth slope per texel; units are steps of the depth format (the
// settings API's polygon_offset). Doubling steps: acne and leak change with the offset's
// order of magnitude, and the plugin's defaults ([1, 8] nearest, [2, 8] pcf) lie on it.
inline constexpr std::array<double, 7> kOffsetFactors = {0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0};
inline constexpr std::array<double, 10> kOffsetUnits = {0.0, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0};
inline constexpr long kOffsetLatticeSize = static_cast<long>(kOffsetFactors.size() * kOffsetUnits.size());

// The default [factor, units] the plugin gives `base` (its variant and filter).
std::array<double, 2> defaultOffset(const Candidate& base);

// `bases`: per light, the setting to fit (nullopt: that light has none to fit). Measures
// through `measurer`; results per light in the same order.
std::vector<std::optional<OffsetFitResult>> fitOffsets(LockstepMeasurer& measurer,
                                                       const std::vector<std::optional<Candidate>>& bases);

} // namespace shadowmap_tune
