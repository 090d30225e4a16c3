#pragma once
// How many texels a light's map needs so that one texel, seen on screen, spans at most a
// pixel: the atlas sizes each map by it (plugin/AtlasMaps.h), so a lamp far away or small on
// screen gets a small map and a near one a large map. No GL.
//
// At each sample point the map's NDC is stepped along its x and y and the step seen on
// screen: a texel of a map of side res is 2 / res of NDC, so it spans at most a pixel where
// res >= 2 * (pixels per unit of NDC), the largest over the points where the light reaches a
// receiver in front of the camera. The derivative is taken over a step of 1e-4 of NDC: its
// linearization error is of the order of that step, far below a texel's own variation.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace shadowmap {

// Between the samples of receiverSamples' grid a texel can be wider on screen than at any
// sample: measured over 200 random lamps, floors and boxes (ScreenMatchedResolutionTest) up
// to 1.11 times the widest sample's. The size is taken this much larger.
inline constexpr double kMatchedSampleMargin = 1.15;

// The largest res over `points` inside the light's clip volume and between the camera's near
// and far planes, on screen or beside it, times kMatchedSampleMargin; 0 when no point is.
double screenMatchedResolution(const glm::dmat4& lightViewProjection, const glm::dmat4& cameraViewProjection,
                               int width, int height, std::span<const glm::dvec3> points);

// Where a light's map lands on the receivers: where each ray of a raysPerSide x raysPerSide
// grid over the map (its NDC from -1 to 1 on both axes, edges included) enters each receiver
// box (world space) between the map's near and far planes: the surfaces facing the light,
// lit or in a shadow the map must draw.
inline constexpr int kMatchedSampleRaysPerSide = 17;
std::vector<glm::dvec3> receiverSamples(const glm::dmat4& lightViewProjection, std::span<const engine::Aabb> receivers,
                                        int raysPerSide = kMatchedSampleRaysPerSide);

// The box around a view-projection's frustum (its eight NDC corners unprojected); empty when
// a corner is not finite (an infinite far plane).
engine::Aabb frustumBounds(const glm::dmat4& viewProjection);

} // namespace shadowmap
