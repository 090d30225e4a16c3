#pragma once
// How many texels a light's map needs so that one texel, seen on screen, spans at most a
// pixel: the atlas sizes each map by it (plugin/AtlasMaps.h), so a lamp far away or small on
// screen gets a small map and a near one a large map. No GL.
//
// At each sample, a point of a receiver's surface with its normal, the map's coordinates and
// the window's are differentiated along the surface (perspective divides included), and a
// whole unit of the map's s and t carried onto the screen: a texel of a map of side res is
// 1 / res of that, so it spans at most a pixel where res >= the longer of the two steps, the
// largest over the samples. That is LogPSM's m (docs/metrics.md), which the truth's texel
// metric measures with code of its own.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace shadowmap {

// Between the samples of receiverSamples' grid a texel can be wider on screen than at any
// sample: measured over 200 random lamps, floors and boxes (ScreenMatchedResolutionTest) up
// to 1.16 times the widest sample's. The size is taken 1.25 times larger: that and room.
inline constexpr double kMatchedSampleMargin = 1.25;

// A point of a receiver's surface and its unit normal (world space).
struct ReceiverSample {
    glm::dvec3 point;
    glm::dvec3 normal;
};

// The largest res over the samples inside the light's clip volume and between the camera's
// near and far planes, on screen or beside it (and not edge-on to the light), times
// kMatchedSampleMargin; 0 when no sample is.
double screenMatchedResolution(const glm::dmat4& lightViewProjection, const glm::dmat4& cameraViewProjection,
                               int width, int height, std::span<const ReceiverSample> samples);

// Where a light's map lands on the receivers: where each ray of a raysPerSide x raysPerSide
// grid over the map (its NDC from -1 to 1 on both axes, edges included) enters each receiver
// box (world space) between the map's near and far planes, with that face's normal: the
// surfaces facing the light, lit or in a shadow the map must draw.
inline constexpr int kMatchedSampleRaysPerSide = 17;
std::vector<ReceiverSample> receiverSamples(const glm::dmat4& lightViewProjection, std::span<const engine::Aabb> receivers,
                                        int raysPerSide = kMatchedSampleRaysPerSide);

// The box around a view-projection's frustum (its eight NDC corners unprojected); empty when
// a corner is not finite (an infinite far plane).
engine::Aabb frustumBounds(const glm::dmat4& viewProjection);

} // namespace shadowmap
