#pragma once
// Woo's midpoint map: per layer, the nearest surface z1 first (a transient of the map's
// size), then a pass peeling it: fragments behind z1 write the midpoint (z + z1) / 2 and
// the depth test keeps the nearest, so the layer holds the midpoint between the two
// nearest surfaces (shaders/depth/woo_peel.frag).
#include "technique/DepthTechnique.h"

namespace shadowmap {

class WooDepth final : public DepthTechnique {
public:
    Variant variant() const override { return Variant::Woo; }
    std::vector<const DepthProgram*> programs() const override;
    void addLayerPasses(const LayerPasses& passes) const override;
    // The peel draws them: the surface behind a caster may be a receiver that casts nothing
    // (a ground), and a midpoint taken with the far plane instead lies beyond it, lit.
    bool drawsNonCastingReceivers() const override { return true; }
};

} // namespace shadowmap
