#pragma once
// shadowmap-bench's command line: which scenes, which settings to sweep, where to write.
// Parsing checks every value (unknown variant, format or filter, bad number) and throws
// std::invalid_argument with one line naming the flag and the value.
#include "engine/scene/Scene.h"
#include "shadowmap/ShadowSettings.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowmap_bench {

struct BenchOptions {
    std::string config;               // default: the source tree's content/engine.json
    std::vector<std::string> scenes;  // default: the showcase and Debian's 2CylinderEngine.glb
    // Default list only: the alpha-masked scenes and their opaque twins, swept over the
    // variants and resolutions at one depth format and filter (maskedSettings in Sweep.h),
    // so that they add minutes, not a full grid each, to the default sweep.
    std::vector<std::string> maskedScenes;
    bool defaultScenes = true;        // no --scene given: a missing optional model is skipped
    std::string camera;               // empty: the scene's first camera, else a framing one
    int width = 0, height = 0;        // defaults below
    std::vector<std::string> variants;
    std::vector<int> resolutions;
    std::vector<std::string> depthFormats;
    std::vector<std::string> filters;
    // The optional axes (SweepAxes.h); empty: not swept, the key is not written and each
    // light keeps the value its scene or the engine config gives it.
    // --light-radii, --angular-diameters: the k-th of each form the k-th light size step
    // (spot and point lights take the radius, directional lights the diameter); given both,
    // the lists have one length; given one, the other type of light keeps its own size.
    std::vector<double> lightRadii, angularDiameters;
    std::vector<double> filterRadii;  // --filter-radii: pcf, vsm and evsm rows (vsm, evsm: the moments' blur)
    std::vector<int> filterTaps;      // --filter-taps: pcss rows and pcf rows with a filter radius > 0
    std::vector<double> bleedReductions;  // --bleed-reductions: vsm and evsm rows only
    std::vector<double> normalOffsets;  // --normal-offsets: every row
    // Directional lights only (a spot or point light keeps its own value, and its row is
    // written once, not once per value): --projections uniform,lispsm; --cascades auto,1..4
    // (shadowmap::kAutoCascades for auto); --stables true,false, rows whose projection is
    // not lispsm (a warp is never stable: the plugin ignores the key there; one map, cascades
    // 1 without a shadow_distance, is fitted either way).
    std::vector<shadowmap::Projection> projections;
    std::vector<int> cascades;
    std::vector<bool> stables;
    int frames = 0;
    // --shimmer N: also measure shimmer on N frames of a slow pan (evaluation/CameraPath.h); 0: not.
    int shimmerFrames = 0;
    // --near D: also score each light on the pixels within D (world units) of the camera; 0: not.
    double nearDistance = 0.0;
    // Added to every scene that has no light (e.g. Debian's 2CylinderEngine.glb);
    // nullopt: --key-light none, such scenes are reported as an error.
    std::optional<engine::Light::Type> keyLight = engine::Light::Type::Spot;
    // --time T,...: every scene measured posed at each listed time (all its animations, as
    // engine-render --time poses them); the scene column then reads "<stem>@<T>s". Empty:
    // the rest pose, the scene column the stem.
    std::vector<double> times;
    bool ground = false;  // --ground: a receiving ground under every scene (tools/common/SceneLighting.h)
    std::string out;
    // --shard K/N: run every N-th job only (Shards.h); count 1: all of them.
    int shardIndex = 1, shardCount = 1;
    std::vector<std::string> merge;  // --merge DIR...: merge these shards' results, render nothing
    bool help = false;
};

// --help's text; the settings it lists come from the shadow plugin's settings API.
const char* benchUsage();

// Throws std::invalid_argument with one line naming the flag and the reason.
BenchOptions parseBenchOptions(int argc, char** argv);

} // namespace shadowmap_bench
