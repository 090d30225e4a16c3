#pragma once
// The "light's view" debug view: a camera placed at a light, so the scene is seen as the
// light sees it (the first picture of Kilgard's GDC 2000 slides: every surface it lights is
// visible, shadows are hidden behind what casts them).
//  - spot: the shadow map's own L and field of view (its shadow view's; without a map, the
//    cone's), aspect 1: the same picture as its depth map;
//  - directional: the plugin's L (the fitted box's face toward the light; a placement from
//    the scene's bounds when the plugin reported none) and an orthographic box around the
//    whole scene (the plugin fits x/y to what the camera sees, which it does not report);
//  - point: from the light toward the scene's centre, wide enough for the scene's bounding
//    sphere (40 to 120 degrees): a point light sees all around, a cube would be six views.
// Near/far bracket the scene's bounds. The image is square (`size` pixels a side).
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

namespace engine_view {

// `shadow`: the light's shadow view of the last frame, or null.
engine::FrameCamera lightCamera(const engine::Scene& scene, int slot, const engine::ShadowView* shadow, int size);

} // namespace engine_view
