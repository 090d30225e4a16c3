#pragma once
// The shadow error metrics of docs/metrics.md, as fractions of |E| (the bench
// prints percent). Pure CPU, no GL, no Embree.
//
//   acne  (false shadow) = sum over E with truth lit      of (1 - shade) / |E|
//   leak  (false light)  = sum over E with truth shadowed of shade       / |E|
//   error = acne + leak
// and the same on E minus the pixels next to a truth shadow edge ("NoEdge"), where a
// one-pixel disagreement says more about sampling than about the algorithm.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace truth {

struct ShadowErrors {
    double acne = 0.0, leak = 0.0, error = 0.0;
    double acneNoEdge = 0.0, leakNoEdge = 0.0, errorNoEdge = 0.0;
    std::size_t evaluated = 0;        // |E|
    std::size_t evaluatedNoEdge = 0;  // |E minus edge pixels|
    // Against a fractional truth (softShadowErrors): the mean |t - s| over the penumbra, the
    // pixels of E where truth or shade lies strictly between 0 and 1; 0 / 0 otherwise.
    double penumbraError = 0.0;
    std::size_t evaluatedPenumbra = 0;
};

// All images are width*height, rows in the same order (top first as captured):
//   truth      1 = lit, 0 = shadowed (RayTracedVisibility)
//   shade      the algorithm's shadow term in [0,1] (values outside are clamped)
//   evaluation 1 = pixel in E (evaluationSet)
//   covered    1 = some surface there (SurfaceBuffer::covered): only covered neighbours
//              can make an edge, so a silhouette against the background is not one.
ShadowErrors shadowErrors(int width, int height, std::span<const std::uint8_t> truth,
                          std::span<const float> shade, std::span<const std::uint8_t> evaluation,
                          std::span<const std::uint8_t> covered);

// The same metrics against the area truth (RayTracedVisibility::litFraction: the lit fraction
// t of each pixel's footprint), the truth a filtered shade s approximates:
//   acne = sum over E of max(t - s, 0) / |E|,   leak = sum over E of max(s - t, 0) / |E|
// (for t in {0,1} these are the binary definitions above). "NoEdge" leaves out the pixels
// next to an edge of the binary `truth`, as above; the full figures are the ones that judge
// a filter, whose whole difference is at edges.
ShadowErrors areaShadowErrors(int width, int height, std::span<const float> litFraction,
                              std::span<const std::uint8_t> truth, std::span<const float> shade,
                              std::span<const std::uint8_t> evaluation,
                              std::span<const std::uint8_t> covered);

// The metrics against the truth of a light with a size (RayTracedVisibility::visibleFraction:
// the visible fraction t of the light from each pixel's surface point), the truth a soft
// filter (PCSS) approximates: acne and leak as in areaShadowErrors (error = mean |t - s| over
// E), "NoEdge" leaving out the pixels next to an edge of the binarised truth (t >= 0.5 lit),
// and the penumbra figures: E where t or s is strictly between 0 and 1 (after clamping s;
// an 8-bit mask's shade comes in steps of 1/255), where a soft shadow's quality shows.
ShadowErrors softShadowErrors(int width, int height, std::span<const float> visibleFraction,
                              std::span<const float> shade, std::span<const std::uint8_t> evaluation,
                              std::span<const std::uint8_t> covered);

// An 8-bit shadow mask (engine-render --shadow-mask: 255 = lit, 0 = shadowed) as shade.
std::vector<float> shadeFromMask8(std::span<const std::uint8_t> mask);

// 1 where a covered pixel's truth differs from that of a covered 8-neighbour. Both sides of
// a shadow boundary are marked, which is "within 1 px of the edge" (the edge runs between
// pixels).
std::vector<std::uint8_t> truthEdges(int width, int height, std::span<const std::uint8_t> truth,
                                     std::span<const std::uint8_t> covered);

} // namespace truth
