#pragma once
// The uniform block's entries a soft filter (pcss) reads for one light: how large the light
// is in each layer's map coordinates and how the layer's window depth turns into distance
// (shaders/shadow_data.glsl, softLayers, says what each component holds).
// Each projection packs its layers with these; a light without a size packs zero sizes (its
// hard lookup never reads them) and the depth terms, which the moments lookups read.
#include "plugin/ShadowBlock.h"
#include "technique/LightState.h"

namespace shadowmap {

// A 2D map's or one cascade's layer (its view's projection and depth range).
glm::vec4 softLayer(const LightView& view, const LightState& light);
// A point light's cube: faces are 90-degree perspective views whose map coordinates are the
// face's tangents, with the cube's near and far.
glm::vec4 softCubeLayer(const PointLightViews& views, const LightState& light);

} // namespace shadowmap
