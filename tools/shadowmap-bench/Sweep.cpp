#include "Sweep.h"

#include "SceneLighting.h"

#include "ShadowEvaluation.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"
#include "engine/util/Error.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace shadowmap_bench {

namespace {

// The named camera, else the scene's first, else one framing the scene (as engine-render).
// Writes the setting into every light's extras.shadow, which the plugin's prepareScene
// reads over its config defaults; other keys the scene sets (polygon_offset, dimming) stay.
// A malformed extras.shadow is left alone for the plugin to report.
void applyToEveryLight(engine::Scene& scene, const ShadowSetting& setting) {
    for (engine::Light& light : scene.lights) {
        if (light.extras.is_null()) light.extras = nlohmann::json::object();
        if (!light.extras.is_object()) continue;
        nlohmann::json& shadow = light.extras["shadow"];
        if (!shadow.is_null() && !shadow.is_object()) continue;
        shadow["variant"] = setting.variant;
        shadow["resolution"] = setting.resolution;
        shadow["depth_format"] = setting.depthFormat;
        shadow["filter"] = setting.filter;
    }
}

BenchRow makeRow(const BenchScene& scene, const ShadowSetting& setting, double frameMs,
                 const evaluation::LightResult& light) {
    BenchRow row;
    row.scene = scene.name;
    row.light = light.light;
    row.setting = setting;
    row.shadowMs = light.shadowMs;
    row.frameMs = frameMs;
    row.acne = 100.0 * light.errors.acne;
    row.leak = 100.0 * light.errors.leak;
    row.error = 100.0 * light.errors.error;
    row.errorNoEdge = 100.0 * light.errors.errorNoEdge;
    row.areaAcne = 100.0 * light.areaErrors.acne;
    row.areaLeak = 100.0 * light.areaErrors.leak;
    row.areaError = 100.0 * light.areaErrors.error;
    return row;
}

} // namespace

std::vector<BenchScene> loadBenchScenes(const BenchOptions& options) {
    std::vector<BenchScene> scenes;
    const std::vector<ShadowSetting> full = sweepSettings(options), masked = maskedSettings(options);
    std::vector<std::pair<std::string, const std::vector<ShadowSetting>*>> requests;
    for (const std::string& path : options.scenes) requests.emplace_back(path, &full);
    for (const std::string& path : options.maskedScenes) requests.emplace_back(path, &masked);
    for (const auto& [path, settings] : requests) {
        if (options.defaultScenes && !std::filesystem::exists(path)) {
            const bool debianModel = path.rfind("/usr/share/", 0) == 0;
            std::cerr << "shadowmap-bench: skipping " << path << ": not found ("
                      << (debianModel ? "Debian package assimp-testmodels" : "see tools/scripts/") << ")\n";
            continue;
        }
        BenchScene bench;
        bench.name = std::filesystem::path(path).stem().string();
        // Two files with one stem (a/scene.gltf, b/scene.gltf) must stay apart in the results.
        for (const BenchScene& other : scenes)
            if (other.name == bench.name) bench.name += '_' + std::to_string(scenes.size() + 1);
        bench.path = path;
        std::vector<std::string> warnings;
        bench.scene = engine::loadGltf(path, &warnings);
        for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
        if (bench.scene.lightInstances.empty() && !options.keyLight)
            engine::throwInputError(path, "", "the scene has no light (add one with --key-light)");
        // The same key light and ground as engine-render and engine-view give with the same
        // options; the key light only where the scene has none (a sweep measures the scene's).
        tools::SceneLighting lighting;
        if (bench.scene.lightInstances.empty()) lighting.keyLight = options.keyLight;
        lighting.ground = options.ground;
        for (const std::string& note : tools::stageScene(bench.scene, path, lighting).notes)
            std::cerr << "shadowmap-bench: " << bench.name << ": " << note << "\n";
        if (bench.scene.meshInstances.empty()) engine::throwInputError(path, "", "the scene has no mesh to shadow");
        bench.camera = engine::chooseCamera(bench.scene, options.camera, options.width, options.height, path);
        bench.shadowedLights = std::min<int>(bench.scene.lightInstances.size(), engine::kMaxLights);
        bench.settings = *settings;
        scenes.push_back(std::move(bench));
    }
    if (scenes.empty()) throw engine::InputError("no scene to sweep (give one with --scene)");
    return scenes;
}

std::vector<ShadowSetting> sweepSettings(const BenchOptions& options) {
    std::vector<ShadowSetting> settings;
    for (const std::string& variant : options.variants)
        for (int resolution : options.resolutions)
            for (const std::string& format : options.depthFormats)
                for (const std::string& filter : options.filters)
                    settings.push_back({variant, resolution, format, filter});
    return settings;
}

std::vector<ShadowSetting> maskedSettings(const BenchOptions& options) {
    const auto preferred = [](const std::vector<std::string>& listed, const std::string& name) {
        return std::find(listed.begin(), listed.end(), name) != listed.end() ? name : listed.front();
    };
    // The plugin's default format and filter, when listed: what a scene gets unless it asks.
    const shadowmap::ShadowSettings defaults;
    std::vector<ShadowSetting> settings;
    for (const std::string& variant : options.variants)
        for (int resolution : options.resolutions)
            settings.push_back({variant, resolution, preferred(options.depthFormats, shadowmap::toString(defaults.depthFormat)),
                                preferred(options.filters, shadowmap::toString(defaults.filter))});
    return settings;
}

std::vector<BenchRow> runSweep(std::vector<BenchScene>& scenes, const engine::RendererConfig& rendererConfig,
                               const std::vector<engine::RenderPlugin*>& plugins, int frames,
                               const RowCallback& onRow) {
    int total = 0;
    for (const BenchScene& scene : scenes) total += scene.shadowedLights * static_cast<int>(scene.settings.size());

    engine::Renderer renderer(rendererConfig, plugins);
    engine::FrameRequest warmup;
    std::vector<BenchRow> rows;
    for (BenchScene& scene : scenes) {
        // The evaluator builds the scene's Embree BVH once; settings change no geometry.
        evaluation::ShadowEvaluator evaluator(renderer, scene.scene);
        evaluator.setAreaTruth(true);
        for (std::size_t index = 0; index < scene.settings.size(); ++index) {
            const ShadowSetting& setting = scene.settings[index];
            applyToEveryLight(scene.scene, setting);
            // The first setting comes with the scene's upload; after it only settings change:
            // the plugin re-reads every light's extras.shadow and re-renders the maps whose
            // settings changed, and the geometry stays on the GPU.
            if (index == 0) renderer.setScene(scene.scene);
            else renderer.reloadSettings();
            // Untimed until nothing new compiles: llvmpipe compiles shaders at their first
            // draw, and new maps are allocated. Four frames past the first are more than the
            // two warm-up ever needs (the shade cache's fetching programs come in the second).
            warmup.camera = scene.camera;
            renderer.warmUp(warmup, 1, 5);
            const evaluation::ViewResult view = evaluator.evaluate(scene.camera, frames);
            for (const evaluation::LightResult& light : view.lights) {
                rows.push_back(makeRow(scene, setting, view.frameMs, light));
                onRow(rows.back(), static_cast<int>(rows.size()), total);
            }
        }
    }
    return rows;
}

} // namespace shadowmap_bench
