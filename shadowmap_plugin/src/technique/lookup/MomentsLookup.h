#pragma once
// Filterable shadow maps: variance (vsm; Donnelly and Lauritzen 2006) and exponential
// variance (evsm; Lauritzen and McCool 2008) maps. After a layer's depth passes, the plugin's
// moments passes (plugin/MomentsPasses.h) turn the depth map into a texture of depth moments
// (shaders/moments/moments.glsl: of a depth linear in the distance from the light), blurred
// by filter_radius and, for a 2D map, mipmapped; the lookup reads them with one filtered
// fetch and bounds the lit share by Chebyshev's inequality, less the bleed_reduction. Soft
// edges at the cost of one pass per layer instead of many taps per pixel, and light that
// bleeds where occluders overlap (evsm's warps bleed far less; docs/filterable-maps.md
// measures both). The GLSL is shaders/lookup/vsm.glsl and evsm.glsl.
#include "technique/MapLookup.h"

namespace shadowmap {

class MomentsLookup final : public MapLookup {
public:
    // channels: 2 (vsm: u, u^2) or 4 (evsm: both warps and their squares).
    MomentsLookup(Filter filter, int channels, const char* glslName) : filter_(filter), channels_(channels), glslName_(glslName) {}
    Filter filter() const override { return filter_; }
    bool bilinearCompare() const override { return false; }
    bool comparesInHardware() const override { return false; }
    int momentChannels() const override { return channels_; }
    const char* glslName() const override { return glslName_; }
    // The blur's reach, and with mipmaps the whole map: a coarse level's texel averages
    // texels far from the point, so no caster may be left out (UnseenShadows.h).
    double reachTexels(const ShadowSettings& settings) const override {
        return settings.momentsMipmaps ? settings.resolution : settings.filterRadius + 1.0;
    }
    const char* glsl() const override;  // shaders/lookup/vsm.glsl or evsm.glsl

private:
    Filter filter_;
    int channels_;
    const char* glslName_;
};

} // namespace shadowmap
