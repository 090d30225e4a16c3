#include "Sweep.h"

#include "AnimationPlayback.h"
#include "SceneLighting.h"

#include "CameraPath.h"
#include "SettingTrial.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"
#include "engine/util/FormatNumber.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>

namespace shadowmap_bench {

namespace {

// Writes the setting into every light's extras.shadow, which the plugin's prepareScene
// reads over its config defaults; other keys the scene sets (polygon_offset, dimming) stay.
void applyToEveryLight(engine::Scene& scene, const ShadowSetting& setting) {
    const nlohmann::json shadow = {{"variant", setting.variant},
                                   {"resolution", setting.resolution},
                                   {"depth_format", setting.depthFormat},
                                   {"filter", setting.filter}};
    for (std::size_t light = 0; light < scene.lights.size(); ++light)
        evaluation::setLightShadow(scene, static_cast<int>(light), shadow);
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
    if (scene.nearDistance > 0.0) {
        row.nearError = 100.0 * light.nearErrors.error;
        row.nearErrorNoEdge = 100.0 * light.nearErrors.errorNoEdge;
    }
    return row;
}

} // namespace

namespace {

// One scene of the sweep: `path` loaded, posed at `time` (nullopt: at rest), lit and framed.
// `taken` are the names of the scenes loaded before it.
BenchScene loadBenchScene(const BenchOptions& options, const std::string& path, std::optional<double> time,
                          const std::vector<BenchScene>& taken) {
    BenchScene bench;
    bench.name = std::filesystem::path(path).stem().string();
    if (time) bench.name += std::string("@").append(engine::formatNumber(*time)).append("s");
    // Two files with one stem (a/scene.gltf, b/scene.gltf) must stay apart in the results.
    for (const BenchScene& other : taken)
        if (other.name == bench.name) bench.name += '_' + std::to_string(taken.size() + 1);
    bench.path = path;
    std::vector<std::string> warnings;
    bench.scene = engine::loadGltf(path, &warnings);
    const bool firstPose = !time || *time == options.times.front();
    if (firstPose)
        for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
    if (time) {
        tools::AnimationPlayback playback;
        playback.animations = tools::selectAnimations(bench.scene, path, "--time", "all");
        playback.startSeconds = *time;
        if (playback.animations.empty() && firstPose)
            std::cerr << "warning: --time: " << path << " has no animations (measured at rest)\n";
        tools::poseScene(bench.scene, playback, *time);
    }
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
    bench.nearDistance = options.nearDistance;
    if (options.shimmerFrames > 0) bench.shimmerPath = evaluation::onePixelPan(bench.camera, options.shimmerFrames);
    return bench;
}

// The settings every light of `bench` accepts: a soft filter needs each light to have a size
// (in its extras.shadow or the config's defaults); a scene where one has none is swept
// without that filter, with a note naming the light, rather than failing the sweep.
std::vector<ShadowSetting> acceptedSettings(const BenchScene& bench, const std::vector<ShadowSetting>& settings,
                                            const nlohmann::json& pluginSettings) {
    const shadowmap::ShadowSettings defaults =
        shadowmap::parsePluginSettings(pluginSettings, "engine config").lightDefaults;
    std::vector<ShadowSetting> accepted;
    std::vector<std::string> refusedFilters;
    for (const ShadowSetting& setting : settings) {
        std::optional<std::string> refusal;
        for (int instance = 0; instance < bench.shadowedLights && !refusal; ++instance) {
            const engine::Light& light = bench.scene.lights[bench.scene.lightInstances[instance].light];
            const std::string object = "light \"" + engine::lightInstanceName(bench.scene, instance) + "\"";
            shadowmap::ShadowSettings lightSettings = defaults;
            if (light.extras.is_object() && light.extras.contains("shadow"))
                shadowmap::applySettings(lightSettings, light.extras["shadow"], bench.path, object);
            shadowmap::applySettings(lightSettings, {{"filter", setting.filter}}, bench.path, "--filters");
            try {
                shadowmap::checkFilterForType(lightSettings, light.type, bench.path, object);
            } catch (const engine::InputError& error) {
                refusal = error.what();
            }
        }
        if (!refusal) {
            accepted.push_back(setting);
        } else if (std::find(refusedFilters.begin(), refusedFilters.end(), setting.filter) == refusedFilters.end()) {
            refusedFilters.push_back(setting.filter);
            std::cerr << "shadowmap-bench: " << bench.name << ": no filter " << setting.filter << " rows: " << *refusal
                      << "\n";
        }
    }
    return accepted;
}

} // namespace

std::vector<BenchScene> loadBenchScenes(const BenchOptions& options, const nlohmann::json& pluginSettings) {
    std::vector<BenchScene> scenes;
    const std::vector<ShadowSetting> full = sweepSettings(options), masked = maskedSettings(options);
    std::vector<std::pair<std::string, const std::vector<ShadowSetting>*>> requests;
    for (const std::string& path : options.scenes) requests.emplace_back(path, &full);
    for (const std::string& path : options.maskedScenes) requests.emplace_back(path, &masked);
    std::vector<std::optional<double>> poses(options.times.begin(), options.times.end());
    if (poses.empty()) poses.push_back(std::nullopt);
    for (const auto& [path, settings] : requests) {
        if (options.defaultScenes && !std::filesystem::exists(path)) {
            const bool debianModel = path.rfind("/usr/share/", 0) == 0;
            std::cerr << "shadowmap-bench: skipping " << path << ": not found ("
                      << (debianModel ? "Debian package assimp-testmodels" : "see tools/scripts/") << ")\n";
            continue;
        }
        for (const std::optional<double>& time : poses) {
            scenes.push_back(loadBenchScene(options, path, time, scenes));
            scenes.back().settings = acceptedSettings(scenes.back(), *settings, pluginSettings);
        }
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
    std::vector<BenchRow> rows;
    for (BenchScene& scene : scenes) {
        if (scene.settings.empty()) continue;  // another shard's
        evaluation::SettingTrial trial(renderer, scene.scene, {scene.camera}, frames);
        trial.setAreaTruth(true);
        trial.setNearDistance(scene.nearDistance);
        for (const ShadowSetting& setting : scene.settings) {
            applyToEveryLight(scene.scene, setting);
            const evaluation::TrialResult measured = trial.measure();
            const std::vector<evaluation::LightShimmer> shimmer = trial.shimmer(scene.shimmerPath);
            for (const evaluation::LightResult& light : measured.lights) {
                rows.push_back(makeRow(scene, setting, measured.frameMs, light));
                for (const evaluation::LightShimmer& moving : shimmer)
                    if (moving.slot == light.slot) rows.back().shimmer = 100.0 * moving.count.fraction();
                onRow(rows.back(), static_cast<int>(rows.size()), total);
            }
        }
    }
    return rows;
}

} // namespace shadowmap_bench
