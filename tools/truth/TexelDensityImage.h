#pragma once
// The texel-density picture (docs/metrics.md, "Texel on screen"): LogPSM's m at every pixel
// (TexelMetric.h) and its heat map, shared by engine-render --texel-density and engine-view's
// density view. Pure CPU, no GL.
#include "truth/HeatScale.h"
#include "truth/SurfaceCapture.h"

#include "engine/render/ShadowView.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace truth {

// The heat map's scale (HeatScale.h: log2 interpolation), the one place it is defined.
// Blue: a texel smaller than half a pixel (resolution to spare); green: one texel per pixel
// (the goal); yellow: a texel spans 4 pixels (its steps show); red: 16 pixels or more (blocky).
inline constexpr std::array<HeatStop, 4> kTexelDensityScale = {{
    {0.5, {0, 0, 255}, "blue"},
    {1.0, {0, 255, 0}, "green"},
    {4.0, {255, 255, 0}, "yellow"},
    {16.0, {255, 0, 0}, "red"},
}};
// Where m has no value (not covered, outside the light's evaluation set, no map layer there,
// behind the light or the camera, edge-on to the light): mid grey, no stop's colour.
inline constexpr std::array<std::uint8_t, 3> kTexelDensityNoValue = {128, 128, 128};

// The colour of one m (any value; NaN or infinite: kTexelDensityNoValue), alpha 255.
std::array<std::uint8_t, 4> texelDensityColor(double m);

// RGBA8 heat map of a per-pixel m image, in the image's pixel order.
std::vector<std::uint8_t> texelDensityImage(std::span<const double> m);

// m at every pixel of `surfaces` through the layer of `view` the lookup uses (shadowLayerAt),
// NaN where it has none: outside `evaluated` (evaluationSet: covered, receiving, in the
// light's reach, facing it), no rendered layer, or texelOnScreen has no value. The pixels
// --truth's texel m figures are taken over are exactly the finite ones.
std::vector<double> texelOnScreenImage(const engine::ShadowView& view, const SurfaceBuffer& surfaces,
                                       std::span<const std::uint8_t> evaluated);

// The scale in words, from kTexelDensityScale, for the viewer's overlay and engine-render's
// output: "m (px per texel) <=0.5 blue, 1 green, 4 yellow, >=16 red, log scale; grey: no value".
std::string texelDensityLegend();

} // namespace truth
