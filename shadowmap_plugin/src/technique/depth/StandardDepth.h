#pragma once
// The standard map: one pass per layer drawing every caster's nearest surface.
#include "technique/DepthTechnique.h"

namespace shadowmap {

class StandardDepth : public DepthTechnique {
public:
    Variant variant() const override { return Variant::Standard; }
    void addLayerPasses(const LayerPasses& passes) const override;
};

// The one pass that clears the layer and, when it has casters to draw, draws them: what
// every technique adds for a layer without casters.
void addSingleDepthPass(const LayerPasses& passes);

} // namespace shadowmap
