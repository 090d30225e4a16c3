#pragma once
// The registry of shadow techniques along their three axes: how the map is made
// (DepthTechnique.h, by variant), how it is projected (MapProjection.h, by map kind) and how
// it is looked up (MapLookup.h, by filter). A technique is a class in its axis's folder plus
// one line in its table in Techniques.cpp; nothing else names it.
#include "technique/DepthTechnique.h"
#include "technique/MapLookup.h"
#include "technique/MapProjection.h"

#include <string>
#include <vector>

namespace shadowmap {

// Whether the variant's shadow comes from a depth map: not none (no shadow), not volume
// (stenciled volumes per camera pixel: plugin/VolumeRenderer.h).
inline bool usesDepthMap(Variant variant) { return variant != Variant::None && variant != Variant::Volume; }
// The variant's technique; nullptr for the variants without a map (usesDepthMap).
const DepthTechnique* depthTechnique(Variant variant);
// Every depth technique's programs (DepthTechnique::programs), each once.
std::vector<const DepthProgram*> depthPrograms();
// The projection of a map kind; nullptr for MapKind::None.
const MapProjection* mapProjection(MapKind kind);
// The projection a light of this type gets with this many cascades this frame and its
// shadow_distance (a directional light with one: cascades even for one map).
const MapProjection& projectionFor(engine::Light::Type type, int cascadeCount, double shadowDistance = 0.0);
// The lookup of a filter as such (pcf: its one 2x2 tap).
const MapLookup& mapLookup(Filter filter);
// The lookup a light's settings read its map with: its filter's, widened by filter_radius.
const MapLookup& mapLookupFor(const ShadowSettings& settings);
// A lookup named `glslName` (MapLookup::glslName; lookups of one name share their GLSL and
// sampler types); std::logic_error if none.
const MapLookup& mapLookupNamed(const std::string& glslName);

} // namespace shadowmap
