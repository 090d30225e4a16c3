#pragma once
// A directional light's light-space perspective view (projection "lispsm", math/LispsmWarp.h)
// of what the camera sees: the body is the visible receivers cut by the camera's frustum, or
// by one slice of it (a cascade's), so the warp spends the texels where the camera looks.
// Shared by the single map (FittedMapProjection) and the cascades (CascadedMapProjection).
#include "technique/MapProjection.h"

#include "math/LispsmWarp.h"

#include <optional>

namespace shadowmap {

// A slice's warp (a cascade, or a map ended by shadow_distance) has its centre at twice the
// optimal n. With n_opt a slice from the camera's near plane is short and warped hard, its
// centre a metre or two behind the camera, and large receivers that reach behind the
// camera (the outdoor street's 1 km ground) pass close to it: llvmpipe then rasterized
// their depth with errors the offsets do not cover (4 cascades: 13.7 % of pixels acne; a
// slice to 5.4 m: 28 %). At 2x: 0.09 and 0.63 %, with the same texels within 1.2x; at 3x
// the 5.4 m slice has 0.03 % but longer slices lose more (docs/lispsm.md).
inline constexpr double kSliceWarpNScale = 2.0;

// `slice`: the view depths of a cascade (x near, y far); none: the whole view, from the
// nearest visible receiver. An empty view where no visible receiver lies in it.
LightView fitWarpedView(const LightState& light, const PlanContext& context, const FrustumFitOptions& options,
                        std::optional<glm::dvec2> slice, LispsmFit* chosen);

} // namespace shadowmap
