#pragma once
// How a light's map is projected and laid out: one axis of a shadow technique
// (Techniques.h). A projection fits the light's view(s) to what the frame must hold, says
// which layers of the map the depth passes draw, what the map's content depends on (its
// cache key), and how the lit pass finds a pixel in it (the uniform block's entries and
// the lookup GLSL's layout). Today: the fitted 2D map (spot and directional lights), the
// cube (point lights) and cascades (directional lights); each in projection/.
#include "plugin/HookGlsl.h"
#include "plugin/ShadowBlock.h"
#include "technique/LightState.h"

#include "engine/render/Frame.h"
#include "engine/render/ShadowView.h"
#include "engine/util/Hasher.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowmap {

// One frame's inputs to planning, all CPU data.
struct PlanContext {
    const engine::Scene& scene;
    engine::FrameCamera camera;
    ShadowBounds bounds;     // receivers the camera can see, every caster
    engine::Aabb everything; // every receiver and caster, seen or not (directional lights only)
    // bounds.receivers cut to the camera's frustum (UnseenShadows.h's visibleReceiverParts),
    // made once per frame by planContext for every light's unseen-caster culling; unset:
    // made by each light that needs it.
    std::optional<std::vector<engine::Aabb>> visibleReceiverParts{};
};

struct ProjectionFit {
    bool valid = false;         // false: the light is degenerate (invalidReason says why)
    bool empty = true;          // no visible receiver in any of its views: no map this frame
    std::string invalidReason;
};

// The texture a projection needs.
struct MapShape {
    enum class Target { Texture2D, Cube, Array2D } target = Target::Texture2D;
    int layers = 1;  // what the depth passes render: Array2D its layers, Cube 6 faces, Texture2D 1
    // Layers of the texture object (a cube is one texture of six faces).
    int arrayLayers() const { return target == Target::Array2D ? layers : 1; }
};

// One layer of the map this frame's depth passes render.
struct MapLayer {
    int layer = -1;                 // -1: the 2D map; cube face 0-5; cascade 0..N-1
    glm::dmat4 viewProjection{1.0}; // P_light * L^-1
    bool drawsCasters = true;       // false: cleared only (no receiver in its view)
    int keySlot = -1;               // where its key is recorded: -1 renderedKey, else renderedCascadeKeys[c]
    std::uint64_t keyWhenDone = 0;  // the key it holds once its passes ran (0: recorded by another layer)
};

// What the lit pass's lookup of one light needs from this frame.
struct LookupContext {
    const engine::Scene& scene;
    glm::dmat4 eyeToWorld;  // V
    glm::dmat4 view;        // V^-1
};

class MapProjection {
public:
    virtual ~MapProjection() = default;
    virtual MapKind kind() const = 0;
    // As --stats names the map ("2d", "cube", "cascades").
    virtual const char* name() const = 0;

    // Fits the light's view(s) into light.frame for this frame.
    virtual ProjectionFit fit(LightState& light, const PlanContext& context,
                              const FrustumFitOptions& options) const = 0;
    virtual MapShape shape(const LightState& light) const = 0;
    // Sets frame.mapKey and frame.cacheHit (and the per-layer keys where layers are kept
    // apart): whether the map as last rendered still holds what this frame needs.
    virtual void decideCache(LightState& light, const engine::Scene& scene, std::uint64_t sceneGeneration,
                             bool cacheMaps) const = 0;
    // The layers to render this frame (a layer still right from an earlier frame is left out).
    virtual std::vector<MapLayer> layers(const LightState& light) const = 0;
    // The view whose texels are the smallest: it sets the slope-offset clamp.
    virtual const LightView& finestView(const LightState& light) const = 0;

    // Writes the light's lookup entries of the uniform block for this camera and says which
    // lookup the GLSL makes (slot and units are the caller's); false: a matrix the GPU would
    // get is not finite, so the light must not be looked up.
    virtual bool packLookup(const LightState& light, const LookupContext& context, ShadowBlock& block,
                            HookGlsl::Lookup& lookup) const = 0;
    // What, beyond the map's content, decides the shade a pixel reads (cascades: the splits).
    virtual void addShadeKey(const LightState&, engine::Hasher&) const {}

    // Its part of the light's --stats entry and of the tools' ShadowView.
    virtual void addStats(const LightState& light, nlohmann::json& stats) const = 0;
    virtual void describe(const LightState& light, engine::ShadowView& view) const = 0;
};

} // namespace shadowmap
