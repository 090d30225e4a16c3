#pragma once
// One light's shadow state across frames, without GL: its resolved settings, what the
// planner decided for this frame (LightShadowFrame) and what the map held when last
// rendered. The plugin's LightShadow adds the map texture itself.
#include "math/CascadeFit.h"
#include "math/LightFrustum.h"
#include "math/LispsmWarp.h"
#include "shadowmap/ShadowSettings.h"

#include "engine/graph/PassId.h"
#include "engine/graph/ResourceHandle.h"
#include "engine/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowmap {

// How the map is laid out and projected (one MapProjection each, Techniques.h). Screen: no
// map, a visibility per camera pixel (variant volume: plugin/VolumePasses.h), no projection.
enum class MapKind { None = 0, Map2D = 1, Cube = 2, Cascades = 3, Screen = 4 };

struct LightShadowFrame {
    MapKind kind = MapKind::None;
    LightView view;              // spot / directional
    LispsmFit lispsm;            // directional with projection lispsm: what the warp chose
    PointLightViews pointViews;  // point
    CascadeViews cascades;       // directional with cascades > 1: one view per array layer
    int cascadeCount = 1;        // directional: the cascades this frame (1: one map)
    bool autoCascades = false;   // the count was chosen (cascades: auto) from cascadeNeed
    bool cascadeNeedReused = false;  // ... weighed last frame: nothing it depends on changed
    CascadeNeed cascadeNeed;
    std::string skipReason;      // why no map this frame (variant none, empty frustum...)
    bool emptyFrustum = false;   // skipped because no visible receiver is inside it
    // What the planner has to say about this light this frame, for people (the plugin
    // prints each once per scene and light).
    std::vector<std::string> warnings;
    int facesRendered = 0, facesSkipped = 0;
    std::uint64_t draws = 0, triangles = 0, castersCulled = 0;
    // volume: the silhouette edges extruded and the cap triangles drawn this frame by the CPU,
    // and the casters whose volumes a geometry shader made instead (volume_extrusion "gpu").
    std::uint64_t silhouetteEdges = 0, capTriangles = 0, gpuVolumeCasters = 0;
    std::uint64_t zPassVolumeCasters = 0;  // volume: casters counted with z-pass (no caps)
    bool volumeFillQueried = false;  // volume: the pass drew volumes and counted their fill
    // Casters left out because their shadow reaches no visible receiver (UnseenShadows.h),
    // counted per layer drawn; and per map layer (layerIndex), which ones: empty when none is.
    std::uint64_t castersUnseen = 0;
    std::vector<std::vector<bool>> unseenCasters;
    std::vector<std::string> openCasters;  // backface: casters drawn two-sided
    bool cacheHit = false;                 // the map was still right: no depth pass
    std::vector<std::uint64_t> cascadeKeys;  // cascades: each layer's key (MapCacheKey.h)
    std::vector<bool> cascadeHits;           // cascades: the layer was still right
    std::uint64_t mapKey = 0;              // what the map holds this frame (MapCacheKey.h)
    engine::ResourceHandle map;            // the map in this frame's graph
    engine::ResourceHandle stencilCount;   // volume, when the frame reads the map back: the counts
    std::vector<engine::PassId> passes;    // the passes rendering it this frame, in order
};

struct LightState {
    std::string name;  // for people: the light's name, else its node's, else "light <slot>"
    int slot = -1;     // index into Scene::lightInstances (the lit pass's light slot): its identity
    engine::Light::Type type = engine::Light::Type::Point;
    ShadowSettings settings;
    LightShadowFrame frame;
    // Key of the inputs the map was last rendered from (MapCacheKey.h); 0 = none.
    std::uint64_t renderedKey = 0;
    // Cascades: the key each layer was last rendered from; 0 = none.
    std::vector<std::uint64_t> renderedCascadeKeys;
    // Per map layer (layerIndex): the casters its passes left out when last rendered.
    std::vector<std::vector<bool>> renderedUnseen;
    // cascades: auto: the count chosen last frame (0: none yet), which a small change keeps,
    // and what was weighed for it, with the hash of its inputs (reused while they hold).
    int autoCascadeCount = 0;
    CascadeNeed cascadeNeed;
    std::uint64_t cascadeNeedKey = 0;

    // Graph names, keyed by the light instance (names may repeat or be empty), for the
    // graph's Graphviz output and messages: the map as imported, and per map layer (-1: the
    // 2D map; 0-5: cube faces in GL order; cascades: layers 0..N-1 of the array map) the
    // depth pass (woo: the peel pass) and woo's first layer and the pass drawing it.
    std::string mapResource() const;
    std::string depthPass(int layer) const;
    std::string firstLayerPass(int layer) const;
    std::string firstLayerResource(int layer) const;
    // vsm, evsm: the moments texture as imported, per layer the pass making its moments from
    // the depth map (along s when blurred) and the blur's pass along t with the rows between
    // them.
    std::string momentsResource() const;
    std::string momentsPass(int layer) const;
    std::string momentsBlurPass(int layer) const;
    std::string momentsRowsResource(int layer) const;
    // volume: its visibility per camera pixel as imported, and the pass that makes it.
    std::string visibilityResource() const;
    std::string stencilCountResource() const;
    std::string volumePass() const;
};

} // namespace shadowmap
