#pragma once
// Wang and Molnar's map: only the faces turned away from the light are drawn (front faces
// culled), so the stored depth lies on the far side of each closed caster and the lit
// surface never compares against itself. Valid for closed casters only: open ones (and
// double-sided or alpha-tested ones) are drawn with both faces and the standard offset.
#include "technique/depth/StandardDepth.h"

namespace shadowmap {

class BackfaceDepth final : public StandardDepth {
public:
    Variant variant() const override { return Variant::Backface; }
    void adjustStyle(LightState& light, const DepthStyleContext& context, DepthPassStyle& style) const override;
    // open_casters: the casters drawn two-sided, by node name.
    void addStats(const LightState& light, nlohmann::json& stats) const override;
};

} // namespace shadowmap
