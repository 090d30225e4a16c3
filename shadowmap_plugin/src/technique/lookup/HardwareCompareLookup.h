#pragma once
// The texture unit's depth comparison, one fetch: `nearest` compares one texel, `pcf` the
// four around the point and interpolates the results bilinearly.
#include "technique/MapLookup.h"

namespace shadowmap {

class HardwareCompareLookup final : public MapLookup {
public:
    HardwareCompareLookup(Filter filter, bool bilinear) : filter_(filter), bilinear_(bilinear) {}
    Filter filter() const override { return filter_; }
    bool bilinearCompare() const override { return bilinear_; }
    const char* glslName() const override { return "hardwareCompare"; }
    const char* glsl() const override;  // shaders/lookup/hardwareCompare.glsl

private:
    Filter filter_;
    bool bilinear_;
};

} // namespace shadowmap
