#pragma once
// Which simplified level of a caster (math/CasterLod.h) a depth pass draws (caster_lod): the
// coarsest whose error, at the instance's scale, is at most caster_lod times the world size
// of one of the map's texels at the caster. No GL.
//
// A texel's world size at a point comes from the view's clip space (P_light * L^-1): x/w
// changes by |row0 - (x/w) row3| / w per world unit, and a texel is 2 / resolution of it
// (likewise y; the finer of the two counts). For a spot light or a cube face that is
// 2 d tan(fov / 2) / resolution at depth d, for an orthographic map extent / resolution.
// It is taken at the caster box's corners and the smallest counts: w is affine, so the
// box's point nearest the light's plane is a corner. A box that reaches the light's plane
// (w <= 0 somewhere) has texels down to nothing: level 0.
//
// The choice is a function of the view, the instance's world box and transform and the
// light's settings, all of which the map's cache key holds (MapCacheKey.h): a cached map
// was drawn with the levels the same inputs choose now.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowmap {

// The smallest world size of one texel over the box's corners; 0 when the box reaches the
// light's plane.
double texelSizeAt(const glm::dmat4& viewProjection, const engine::Aabb& worldBounds, int resolution);

// The largest factor by which M stretches a length: its 3x3 part's largest singular value
// (the square root of M^T M's largest eigenvalue, by power iteration), rounded up by 1e-6.
double largestScale(const glm::dmat4& world);

// 0 (the mesh as loaded) or the coarsest level l >= 1 whose errors[l - 1] * scale is at most
// `allowed`; errors ascend (CasterLod.h).
int coarsestLevelWithin(const std::vector<double>& errors, double scale, double allowed);

} // namespace shadowmap
