#pragma once
// How many texels a light's map needs so that one texel, seen on screen, spans at most a
// pixel: the atlas sizes each map by it (plugin/AtlasMaps.h), so a lamp far away or small on
// screen gets a small map and a near one a large map. No GL.
//
// At each sample point the map's NDC is stepped along its x and y and the step seen on
// screen: a texel of a map of side res is 2 / res of NDC, so it spans at most a pixel where
// res >= 2 * (pixels per unit of NDC), the largest over the points where the light reaches a
// receiver the camera sees. The derivative is taken over a step of 1e-4 of NDC: its
// linearization error is of the order of that step, far below a texel's own variation.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace shadowmap {

// The largest res over `points` that both views hold (inside both clip volumes); 0 when
// no point is inside both.
double screenMatchedResolution(const glm::dmat4& lightViewProjection, const glm::dmat4& cameraViewProjection,
                               int width, int height, std::span<const glm::dvec3> points);

// Sample points where a light may reach a receiver: for each receiver box that meets the
// box around the light's frustum (`frustumBounds`), a 3 x 3 x 3 grid over their overlap
// (its corners hold the point nearest any camera outside it).
std::vector<glm::dvec3> receiverSamples(const engine::Aabb& frustumBounds, std::span<const engine::Aabb> receivers);

// The box around a view-projection's frustum (its eight NDC corners unprojected); empty when
// a corner is not finite (an infinite far plane).
engine::Aabb frustumBounds(const glm::dmat4& viewProjection);

} // namespace shadowmap
