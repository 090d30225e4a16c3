#pragma once
// A directional light's light-space perspective view (projection "lispsm", math/LispsmWarp.h)
// of what the camera sees: the body is the visible receivers cut by the camera's frustum, or
// by one slice of it (a cascade's), so the warp spends the texels where the camera looks.
// Shared by the single map (FittedMapProjection) and the cascades (CascadedMapProjection).
#include "technique/MapProjection.h"

#include "math/LispsmWarp.h"

#include <optional>

namespace shadowmap {

// `slice`: the view depths of a cascade (x near, y far); none: the whole view, from the
// nearest visible receiver. An empty view where no visible receiver lies in it.
LightView fitWarpedView(const LightState& light, const PlanContext& context, const FrustumFitOptions& options,
                        std::optional<glm::dvec2> slice, LispsmFit* chosen);

} // namespace shadowmap
