#pragma once
// Percentage-closer soft shadows (Fernando, "Percentage-Closer Soft Shadows", 2005): the
// shadow of a light with a size. A blocker search over the part of the map the light's size
// subtends from the receiver finds the average depth of what lies in front of it; the
// penumbra is as wide as similar triangles make it from there (light size, receiver and
// blocker distances); a filter of that width gives the shade. Taps on a Vogel disk turned
// per pixel; each a 2x2 bilinear comparison of gathered depths (cube maps: one depth).
// The light's size and the layers' scales come from the uniform block
// (technique/SoftShadowLayers.h); the GLSL is shaders/lookup/pcss.glsl.
#include "technique/MapLookup.h"

namespace shadowmap {

class PcssLookup final : public MapLookup {
public:
    // The widest blocker search and filter, in texels of the map. A directional light's map
    // holds casters far in front of a receiver (a street's map reaches up to the roofs), and
    // a search over all that the light's size could hide there is metres wide: its few taps
    // then miss a thin post (the post's shadow fades to dots) and find the receiver's own
    // plane, extrapolated that far, in front of it (speckles). 32 texels keep every
    // penumbra of the showcase and the slab scene (at most about 24), and cost nothing
    // more than the taps they have. Under cascades they are texels of the first cascade in
    // every cascade: one world width, so a penumbra wider than the limit is drawn equally
    // narrow on both sides of a split instead of widening there.
    static constexpr int kMaxRadiusTexels = 32;

    Filter filter() const override { return Filter::Pcss; }
    bool bilinearCompare() const override { return false; }
    bool comparesInHardware() const override { return false; }
    const char* glslName() const override { return "pcss"; }
    // Its blocker search and filter reach at most kMaxRadiusTexels.
    double reachTexels(const ShadowSettings&) const override { return kMaxRadiusTexels + 1.0; }
    const char* glsl() const override;  // shaders/lookup/pcss.glsl
};

} // namespace shadowmap
