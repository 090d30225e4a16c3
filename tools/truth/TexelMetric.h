#pragma once
// The on-screen size of a shadow-map texel (docs/metrics.md, "texel on screen"): LogPSM's
// m, the longer extent in window pixels of one texel of the map projected onto the surface
// and seen by the camera. m <= 1: a texel covers at most a pixel, no perspective aliasing;
// m = 4: each texel's edge spans four pixels of the image.
//
// Pure CPU, in double, no GL: both mappings (map and window) are differentiated exactly
// from their homogeneous matrices, perspective divide included, so perspective maps (spot
// lights, cube faces, warped directional maps) are measured as well as orthographic ones.
#include "engine/render/Frame.h"
#include "engine/render/ShadowView.h"

#include <glm/glm.hpp>

namespace truth {

// m at world point `point` of a surface with unit normal `normal`, seen by `camera`, for
// a map whose clip coordinates are mapViewProjection * world (P_light * L^-1) and which has
// `resolution` texels per side. NaN where there is no value: the point is behind the light
// or the camera (w <= 0), or the map does not resolve the surface (it is edge-on to the
// light, so one direction of the surface collapses to a line of the map).
double texelOnScreen(const glm::dvec3& point, const glm::dvec3& normal, const engine::FrameCamera& camera,
                     const glm::dmat4& mapViewProjection, int resolution);

// The layer of `view` whose texels shade world point `point` seen by `camera`, as the
// plugin's lookup picks it: a cascade by the point's view depth (the first whose far split
// lies beyond it, the last for anything farther), a cube face by the major axis of the
// point minus the light, the one layer of a 2D map. -1: none (no map, or the layer was not
// rendered).
int shadowLayerAt(const engine::ShadowView& view, const engine::FrameCamera& camera, const glm::dvec3& point);

} // namespace truth
