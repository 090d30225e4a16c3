#pragma once
// The shadow plugin's limits and built-in sizes, one home for each number: the settings API
// checks against them, the plugin's math and uniform block are sized by them, and the
// shaders get them as #defines (plugin/ShadowBlock.h).
namespace shadowmap {

// The most cascades a directional light may have (the shaders' MAX_CASCADES).
inline constexpr int kMaxCascades = 4;
// Texels per side of a light's map when nothing says otherwise.
inline constexpr int kDefaultResolution = 2048;

// Filterable (moments) maps, filter vsm and evsm (technique/lookup/MomentsLookup.h).
// EVSM warps the depth u in [0, 1] to e^(c (2u - 1)) and stores it and its square in
// 32-bit float: e^(2c) must stay below FLT_MAX = e^88.7, with room for the blur's sums of up
// to (2 * 16 + 1)^2 texels (e^7): c <= 40.8; 40 is the largest whole exponent within it.
inline constexpr float kMaxEvsmExponent = 40.0f;
// The exponents [positive, negative] when none are set: the positive one at the limit (the
// sharper its warp, the less light bleeds), the negative one small, as in the EVSM4 of the
// literature (Lauritzen and McCool 2008; MJP's "Shadows" sample: 40 and 5).
inline constexpr float kDefaultEvsmExponents[2] = {40.0f, 5.0f};
// The Chebyshev bound's light-bleeding reduction (the bound's lower part cut off and the rest
// stretched over [0, 1]) when none is set: the least acne + leak summed over the showcase's
// three lights, vsm and evsm alike (blur radius 2; 0.1 .. 0.4 measured in
// docs/filterable-maps.md), and it lets none of the bleeding probe's 0.3 through.
inline constexpr double kDefaultBleedReduction = 0.3;

} // namespace shadowmap
