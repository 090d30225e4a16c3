#pragma once
// A vsm or evsm light's moments passes for this frame (technique/lookup/MomentsLookup.h):
// per map layer its depth passes render, the moments of the layer's depths (with
// filter_radius > 0 blurred along s on the way, then along t in a second pass), and a 2D
// map's mipmaps. They read the map's last version, so the depth passes
// stay needed while the lit pass reads only the moments.
#include "plugin/LightShadow.h"
#include "plugin/MomentsRenderer.h"

#include "engine/render/Frame.h"

namespace shadowmap {

// The kind of this light's layers (MomentsDepth's flags; planes and exponents unset).
MomentsDepth momentsKind(const LightShadow& light);

// `map`: the map's version the depth passes left; `moments`: the light's imported moments,
// moved on to the version the last pass wrote.
void addMomentsPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map,
                      engine::ResourceHandle& moments, const MomentsRenderer& renderer);

} // namespace shadowmap
