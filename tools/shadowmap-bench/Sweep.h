#pragma once
// The sweep itself: every scene under every shadow setting, each setting applied to all of
// the scene's lights at once (each light's passes are timed on their own, so one render
// measures every light), timed and compared with ray-traced truth (tools/evaluation).
#include "BenchOptions.h"
#include "BenchRow.h"

#include "engine/plugin/RenderPlugin.h"
#include "engine/config/EngineConfig.h"
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace shadowmap_bench {

struct BenchScene {
    std::string name;  // the file's stem (and pose time), the "scene" column
    std::string path;
    engine::Scene scene;
    engine::FrameCamera camera;
    int shadowedLights = 0;  // lights the lit pass handles (the first kMaxLights)
    std::vector<ShadowSetting> settings;  // what this scene is swept over
    // --shimmer: the camera path (evaluation/CameraPath.h); empty: no shimmer.
    std::vector<engine::FrameCamera> shimmerPath;
    double nearDistance = 0.0;  // --near: also score within this distance of the camera; 0: not
};

// Loads and checks every scene before anything is rendered, so a bad file fails at once,
// not minutes into the sweep. Adds the key light to scenes without one. With the default
// scene list a missing file (the optional Debian model) is skipped with a note on stderr.
// options.scenes get sweepSettings, options.maskedScenes maskedSettings. With options.times
// every file gives one scene per time, posed then (BenchScene::name "<stem>@<T>s").
// Throws engine::InputError naming the file and the reason.
// A scene whose lights cannot all take a setting (pcss on a light without a size, from the
// size step or the scene) is swept without it, with one note per filter and size step;
// `pluginSettings` are the shadow plugin's config settings. The settings are marked
// (markDirectionalRepeats) before any sharding, so a spot or point light's row comes from
// the first job that gives it what it gets.
std::vector<BenchScene> loadBenchScenes(const BenchOptions& options, const nlohmann::json& pluginSettings);

// The cartesian product of the listed variants, resolutions, formats and filters, times the
// optional axes that apply to each (SweepAxes.h); volume (no map) once, not per resolution,
// format and filter.
std::vector<ShadowSetting> sweepSettings(const BenchOptions& options);

// The listed variants and resolutions at one depth format and one filter: d24 and pcf (the
// engine config's defaults) when listed, else the first listed; volume once; times the
// optional axes.
std::vector<ShadowSetting> maskedSettings(const BenchOptions& options);

// Called after each row is measured: `index` counts from 1 to `total`.
using RowCallback = std::function<void(const BenchRow& row, int index, int total)>;

// The rows of a sweep, and how many rows each job (one scene under one setting, in sweep
// order) gave (a job that is a directional repeat gives its directional lights' rows only): a shard records them so --merge can deal jobs back (Shards.h), since rows of
// jobs that differ only in the light size step are otherwise alike but for each light's size.
struct SweepRows {
    std::vector<BenchRow> rows;
    std::vector<int> jobRows;
};

// Needs a current GL context. `plugins` must include the shadow plugin loaded with map
// caching off (otherwise a map renders once and later frames time nothing).
SweepRows runSweep(std::vector<BenchScene>& scenes, const engine::RendererConfig& rendererConfig,
                   const std::vector<engine::RenderPlugin*>& plugins, int frames, const RowCallback& onRow);

} // namespace shadowmap_bench
