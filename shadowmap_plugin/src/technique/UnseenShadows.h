#pragma once
// Receiver-aware caster culling: a caster whose shadow, in one view of a light's map, can
// fall on no receiver the camera sees is left out of that view's depth pass. No GL.
//
// The test, in the view's clip space (P_light * L^-1): the caster's box and each visible
// receiver's box (cut by the camera's frustum) projected to rectangles and depth ranges. The
// caster is needed when some receiver's rectangle, widened by the texels a lookup reads
// around its centre (filter and normal offset: MapLookup::reachTexels), overlaps the
// caster's, and that receiver reaches at least as far from the light as the caster's nearest
// point: a caster wholly behind every overlapping receiver shades none of them. The
// receivers are filed on a grid over the view, so a caster meets only those near it. A caster that is itself a visible
// receiver overlaps itself, so it always stays (its self-shadowing, acne included, is
// untouched). A box partly behind a perspective light covers the whole view.
//
// Woo's midpoint maps are left alone: their second layer is what lies behind a receiver.
//
// Caching (MapCacheKey.h): a map drawn without some casters still serves a later frame
// that needs none of them. The key still covers every caster in the view (moving one that
// was left out re-renders), and a cache hit also needs every caster it left out to be
// unneeded now (keptCachedMapsThatHoldTheNeededCasters).
#include "technique/MapProjection.h"

#include "engine/scene/Aabb.h"
#include "engine/scene/Scene.h"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <vector>

namespace shadowmap {

// Per Scene::meshInstances: true where the instance casts (or, with
// withNonCastingReceivers, is drawn), is inside the view and its shadow can reach no box
// of `visibleReceivers`. reachNdc: the widening of each receiver's rectangle, in clip-space
// units (2 / resolution per texel).
std::vector<bool> castersWithUnseenShadows(const glm::dmat4& viewProjection,
                                           std::span<const engine::Aabb> visibleReceivers,
                                           const engine::Scene& scene, double reachNdc,
                                           bool withNonCastingReceivers);

// Each visible receiver's box cut by the camera's frustum (the box around their
// intersection): a ground plane that stretches far past the view must not count as seen
// where it is not. An infinite far plane leaves the boxes as they are.
std::vector<engine::Aabb> visibleReceiverParts(const std::vector<engine::Aabb>& visibleReceivers,
                                               const engine::FrameCamera& camera);

// The vertices of each visible receiver's box cut by the camera's frustum, whose hulls are
// the parts of the receivers in view (a light-space perspective map's body, LispsmWarp.h);
// an infinite far plane gives the boxes' corners. `depths`: only the slice of the view
// between these view depths (a cascade's).
std::vector<glm::dvec3> visibleReceiverPoints(const std::vector<engine::Aabb>& visibleReceivers,
                                              const engine::FrameCamera& camera,
                                              std::optional<glm::dvec2> depths = std::nullopt);

// Fills light.frame.unseenCasters for every layer the light's projection draws this frame
// (before the cache decision), when the light's cull_unseen_casters is on.
void planUnseenShadows(LightState& light, const PlanContext& context);

// After the key-based cache decision: a map (or cascade layer) whose passes left out a
// caster this frame needs is not a hit.
void keepCachedMapsThatHoldTheNeededCasters(LightState& light);

// The index of a map layer (MapLayer::layer) in the per-layer vectors: 0 for the 2D map.
inline std::size_t layerIndex(int layer) { return layer < 0 ? 0 : static_cast<std::size_t>(layer); }

} // namespace shadowmap
