#pragma once
// Automatic bias: per light, the polygon offset (factor, units) and the normal offset that
// minimize acne + leak against the truth over the views, for the setting the search found
// best among those that draw with a polygon offset. First a descent on the polygon offset's
// lattice, at the light's own normal offset: from the variant's default offset, each round
// measures the four lattice neighbours (factor or units one step up or down) of every light
// at once and moves to the best if it lowers the error; a light stops when none does. Then
// the normal offset: every value of its list at the fitted polygon offset (one render per
// value), the best kept if it lowers the error.
//
// Why after, not jointly (a descent on all three axes, six neighbours a round): on the
// showcase (--budget-ms 10 --views orbit:2, 320x240) the joint descent took 41 renders and
// the fit after it 38 (34 without a normal offset); with light sizes (light_radius 0.1,
// angular_diameter 0.05) 71 against 62. The errors they reached differed by 0.003 % at
// most, either way: the trade the joint descent could make (more normal offset, less
// polygon offset) did not pay there, and two renders more per round did not either.
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
// Normal offsets in texels of the map at the receiver: none, the plugin's default 0.25, and
// doubling steps to 2, a quarter of the plugin's largest (kMaxNormalOffset, beyond which a
// thin caster's shadow detaches visibly); each costs one render. A light's own value off
// this list joins it (normalOffsetAxis).
inline constexpr std::array<double, 5> kNormalOffsets = {0.0, 0.25, 0.5, 1.0, 2.0};
inline constexpr long kOffsetLatticeSize =
    static_cast<long>(kOffsetFactors.size() * kOffsetUnits.size() * kNormalOffsets.size());

// The default [factor, units] the plugin gives `base` (its variant and filter).
std::array<double, 2> defaultOffset(const Candidate& base);

// The normal offsets the fit tries for a light whose own is `own`: kNormalOffsets, with
// `own` among them, ascending (the polygon offset is fitted at `own`, where the light's
// other candidates were measured).
std::vector<double> normalOffsetAxis(double own);

// `bases`: per light, the setting to fit (nullopt: that light has none to fit). Measures
// through `measurer`, the polygon offset at each light's own normal offset
// (LockstepMeasurer::normalOffset); results per light in the same order.
std::vector<std::optional<OffsetFitResult>> fitOffsets(LockstepMeasurer& measurer,
                                                       const std::vector<std::optional<Candidate>>& bases);

} // namespace shadowmap_tune
