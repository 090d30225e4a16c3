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
    Filter filter() const override { return Filter::Pcss; }
    bool bilinearCompare() const override { return false; }
    bool comparesInHardware() const override { return false; }
    const char* glslName() const override { return "pcss"; }
    const char* glsl() const override;  // shaders/lookup/pcss.glsl
};

} // namespace shadowmap
