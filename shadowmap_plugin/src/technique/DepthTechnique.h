#pragma once
// How a light's map is made: one axis of a shadow technique (Techniques.h). A depth
// technique declares, per map layer the projection asks for, the render-graph passes that
// fill it and the style they draw the casters in. Today: standard (the nearest surface),
// woo (the midpoint of the two nearest, by depth peeling) and backface (Wang and Molnar:
// the faces turned away from the light); each in depth/.
#include "technique/DepthPassStyle.h"
#include "technique/LightState.h"
#include "technique/MapProjection.h"

#include "engine/graph/RenderGraph.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowmap {

// Draws the frame's casters into the pass's target with this view-projection and style
// (the plugin's DepthRenderer, counting what it drew).
using CasterDraw = std::function<void(engine::PassContext&, const glm::dmat4& viewProjection, const DepthPassStyle&)>;

// One layer's passes to add.
struct LayerPasses {
    engine::RenderGraph& graph;
    const LightState& light;
    engine::ResourceHandle& map;  // the map's latest version: each write moves it on
    MapLayer layer;
    DepthPassStyle style;
    CasterDraw draw;
    std::function<void()> done;  // call once the layer's last pass has run
    std::vector<engine::PassId>& added;  // receives each pass added, in order
};

// What a technique's style may depend on beyond the light.
struct DepthStyleContext {
    const engine::Scene& scene;
    const std::vector<bool>& closedMeshes;  // per Scene::meshes: closed, not double-sided
};

class DepthTechnique {
public:
    virtual ~DepthTechnique() = default;
    virtual Variant variant() const = 0;
    // Its part of the depth passes' style (the offsets and depth direction are set).
    virtual void adjustStyle(LightState&, const DepthStyleContext&, DepthPassStyle&) const {}
    // Every program its passes draw with (DepthPassStyle::program), compiled before the
    // first frame so that no light's first use compiles one.
    virtual std::vector<const DepthProgram*> programs() const { return {&nearestDepthProgram()}; }
    virtual void addLayerPasses(const LayerPasses& passes) const = 0;
    // Whether some pass draws the receivers that cast no shadow, so that they are part of
    // what the map holds (its cache key).
    virtual bool drawsNonCastingReceivers() const { return false; }
    // Its part of the light's --stats (what it decided this frame beyond the passes).
    virtual void addStats(const LightState&, nlohmann::json&) const {}
};

} // namespace shadowmap
