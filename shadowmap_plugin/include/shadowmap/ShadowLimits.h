#pragma once
// The shadow plugin's limits and built-in sizes, one home for each number: the settings API
// checks against them, the plugin's math and uniform block are sized by them, and the
// shaders get them as #defines (plugin/ShadowBlock.h).
namespace shadowmap {

// The most cascades a directional light may have (the shaders' MAX_CASCADES).
inline constexpr int kMaxCascades = 4;
// Texels per side of a light's map when nothing says otherwise.
inline constexpr int kDefaultResolution = 2048;

} // namespace shadowmap
