#pragma once
// What a shadow plugin publishes about every light's shadow in a frame: the typed contract
// between the plugin and the tools that check or show shadows (the ray-traced evaluation,
// engine-render's map readback and timings, engine-view's light camera and map views, the
// stress tool). Tools read these; the plugin's --stats JSON is a report for people and
// scripts, and the names of its graph passes and resources are for Graphviz and messages.
#include "engine/graph/PassId.h"
#include "engine/graph/ResourceHandle.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace engine {

// One layer of a light's map: the 2D map, one cube face (GL face order) or one cascade.
struct ShadowMapLayer {
    glm::dmat4 lightToWorld{1.0};  // L of this layer's view
    glm::dmat4 projection{1.0};    // P_light
    bool rendered = false;         // false: no receiver in view, cleared to far
    bool redrawn = false;          // its passes ran this frame (false: kept from the cache)
};

struct ShadowView {
    // The light instance (node + light) the view belongs to: its index in
    // Scene::lightInstances, the lit pass's light slot. Names are for people only: two
    // instances may share one, or have none.
    int slot = -1;
    std::string name;
    std::string variant;  // for people: "standard", "woo", "backface", "none" or "volume"
    bool castsShadows = false;  // the light is shadowed at all (its variant is not "none")
    // The effective per-light settings, keyed as in glTF extras.shadow: the plugin's to write
    // and to read (the shadow plugin's shadowmap/ShadowViewSettings.h: usedSettings), so
    // tools need not know its keys and values.
    nlohmann::json settings = nlohmann::json::object();
    // The size of the light the shadow was made for: a truth that scores the shadow samples
    // a light this size. Only the one of the light's type is set; 0: a point, one direction.
    double lightRadius = 0.0;      // spot and point lights: the emitting disk's radius, world units
    double angularDiameter = 0.0;  // directional lights: the cone's apex angle, radians
    // The map this frame; without one, skipReason says why (variant none, nothing in view...).
    bool hasMap = false;
    // No map, but a visibility per camera pixel made this frame or kept from the last
    // (stenciled shadow volumes): renderedThisFrame and passes say what it cost.
    bool hasScreenVisibility = false;
    std::string skipReason;
    bool cube = false;                  // six layers, one per cube face
    std::vector<ShadowMapLayer> layers; // 1 (2D), 6 (cube) or one per cascade; empty without a map
    // Cascades (a directional light's map sliced along the camera's view depth): the N + 1
    // view depths (distance along the camera's -Z) bounding layers 0..N-1, nearest first;
    // empty for any other map.
    std::vector<double> cascadeSplits;
    double nearPlane = 0.0, farPlane = 0.0;  // farPlane may be +infinity
    bool renderedThisFrame = false;     // false: the map was still right (served from the cache)
    // A count of cascades chosen automatically: true when this frame kept last frame's
    // choice (nothing it depends on moved) instead of weighing the counts again.
    bool cascadeCountReused = false;
    // The map in this frame's graph (FrameRequest::shadowMapSlots reads it back), and the
    // passes of this frame's graph that render it (none when cached; their sum is the
    // light's shadow time: FrameResult::shadowPassMs).
    ResourceHandle map;
    std::vector<PassId> passes;
    // With hasScreenVisibility, when the frame asked for the light's map (Frame::
    // mapReadbackRequested): how many shadow volumes hold each camera pixel's surface (R8,
    // the count itself, wrapping at 256; 0: lit), what a map view shows for such a light.
    ResourceHandle stencilCount;
};

// The kind of `view`'s map as the tools report it: "none", "cube", "cascades", "2d", or
// "volumes" for a visibility per camera pixel.
inline const char* mapKindName(const ShadowView& view) {
    if (view.hasScreenVisibility) return "volumes";
    return !view.hasMap ? "none" : view.cube ? "cube" : view.cascadeSplits.empty() ? "2d" : "cascades";
}

} // namespace engine
