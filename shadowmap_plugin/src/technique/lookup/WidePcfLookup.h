#pragma once
// pcf with filter_radius > 0: the hardware's 2x2 bilinear comparison taken filter_taps times
// over a disk of that many texels, turned per pixel, each tap against the receiver's depth
// plane so a wide kernel does not shadow a sloped receiver with itself. Softer edges without
// a light size, at filter_taps fetches; the GLSL is shaders/lookup/widePcf.glsl.
#include "technique/MapLookup.h"

namespace shadowmap {

class WidePcfLookup final : public MapLookup {
public:
    Filter filter() const override { return Filter::Pcf; }
    bool bilinearCompare() const override { return true; }
    const char* glslName() const override { return "widePcf"; }
    double reachTexels(const ShadowSettings& settings) const override { return settings.filterRadius + 1.0; }
    const char* glsl() const override;  // shaders/lookup/widePcf.glsl
};

} // namespace shadowmap
