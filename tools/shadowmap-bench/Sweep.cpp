#include "Sweep.h"

#include "AnimationPlayback.h"
#include "SceneLighting.h"
#include "SweepAxes.h"

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
// reads over its config defaults. Each light starts from its scene's own extras (`original`),
// so a key an earlier row wrote and this one leaves unset (a pcf row's filter_radius before
// a pcss row) goes back to the scene's value; keys the sweep never writes (polygon_offset,
// dimming) stay.
void applyToEveryLight(engine::Scene& scene, const std::vector<engine::Light>& original, const ShadowSetting& setting) {
    for (std::size_t light = 0; light < scene.lights.size(); ++light) {
        scene.lights[light].extras = original[light].extras;
        evaluation::setLightShadow(scene, static_cast<int>(light), lightShadow(setting, scene.lights[light].type));
    }
}

// The light of light instance `instance` (a ShadowView's slot).
const engine::Light& instanceLight(const engine::Scene& scene, int instance) {
    return scene.lights[scene.lightInstances[instance].light];
}

BenchRow makeRow(const BenchScene& scene, const ShadowSetting& setting, const evaluation::TrialResult& measured,
                 const evaluation::LightResult& light) {
    BenchRow row;
    row.scene = scene.name;
    row.light = light.light;
    const engine::Light::Type type = instanceLight(scene.scene, light.slot).type;
    // What the light got: a spot or point light no projection, cascades or stable.
    row.setting = rowSetting(setting, type);
    row.setting.directionalRepeat = false;
    // The row keeps the size its light had (below), not the step's pair (BenchRow.h).
    row.setting.lightRadius = row.setting.angularDiameter = std::nullopt;
    const bool directional = type == engine::Light::Type::Directional;
    row.lightSize = directional ? light.view.angularDiameter : light.view.lightRadius;
    row.shadowMs = light.shadowMs;
    row.frameMs = measured.frameMs;
    row.frameP99Ms = measured.frameP99Ms;
    row.frameMaxMs = measured.frameMaxMs;
    row.acne = 100.0 * light.errors.acne;
    row.leak = 100.0 * light.errors.leak;
    row.error = 100.0 * light.errors.error;
    row.errorNoEdge = 100.0 * light.errors.errorNoEdge;
    row.areaAcne = 100.0 * light.areaErrors.acne;
    row.areaLeak = 100.0 * light.areaErrors.leak;
    row.areaError = 100.0 * light.areaErrors.error;
    // Soft figures on the rows of the lights ranked by them, so that BenchRow::rankedError
    // (which must also work on rows read back by --merge) follows evaluation::rankingTruth.
    if (evaluation::rankingTruth(light) == evaluation::RankingTruth::Soft) {
        row.softError = 100.0 * light.softErrors.error;
        row.softErrorNoEdge = 100.0 * light.softErrors.errorNoEdge;
        row.penumbraError = 100.0 * light.softErrors.penumbraError;
    }
    if (light.texelOnScreen.count > 0) {
        row.texelMean = light.texelOnScreen.mean;
        row.texelP95 = light.texelOnScreen.p95;
    }
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

// Why `bench`'s lights refuse `setting` (the plugin's message naming the first light that
// does), or nullopt when all accept it: a soft filter needs each light to have a size (from
// the size step, its extras.shadow or the config's defaults); filter_radius widens pcf and
// blurs vsm's and evsm's moments only; vsm and evsm refuse lispsm and a spot or point
// light's infinite far plane (shadowmap::checkFilterForType).
std::optional<std::string> refusal(const BenchScene& bench, const ShadowSetting& setting,
                                   const shadowmap::ShadowSettings& defaults) {
    for (int instance = 0; instance < bench.shadowedLights; ++instance) {
        const engine::Light& light = instanceLight(bench.scene, instance);
        const std::string object = "light \"" + engine::lightInstanceName(bench.scene, instance) + "\"";
        shadowmap::ShadowSettings lightSettings = defaults;
        if (light.extras.is_object() && light.extras.contains("shadow"))
            shadowmap::applySettings(lightSettings, light.extras["shadow"], bench.path, object);
        shadowmap::applySettings(lightSettings, lightShadow(setting, light.type), bench.path, "the sweep's setting");
        try {
            shadowmap::checkFilterForType(lightSettings, light.type, bench.path, object);
        } catch (const engine::InputError& error) {
            return error.what();
        }
    }
    return std::nullopt;
}

// The settings every light of `bench` accepts. A scene where one refuses a setting is swept
// without it, with a note naming the light, rather than failing the sweep; one note per
// refused filter and size step, however many rows the other axes multiply it into.
std::vector<ShadowSetting> acceptedSettings(const BenchScene& bench, const std::vector<ShadowSetting>& settings,
                                            const nlohmann::json& pluginSettings) {
    const shadowmap::ShadowSettings defaults =
        shadowmap::parsePluginSettings(pluginSettings, "engine config").lightDefaults;
    std::vector<ShadowSetting> accepted;
    std::vector<std::string> notes;
    for (const ShadowSetting& setting : settings) {
        const std::optional<std::string> reason = refusal(bench, setting, defaults);
        if (!reason) {
            accepted.push_back(setting);
            continue;
        }
        const std::string sizes = setting.sizeLabel();
        const std::string projection =
            setting.projection ? std::string(" with projection ") + shadowmap::toString(*setting.projection) : "";
        const std::string rows = rendersMap(setting.variant) ? "filter " + setting.filter : "variant " + setting.variant;
        const std::string note = "no " + rows + " rows" + (sizes.empty() ? "" : " at" + sizes) + projection + ": " + *reason;
        if (std::find(notes.begin(), notes.end(), note) != notes.end()) continue;
        notes.push_back(note);
        std::cerr << "shadowmap-bench: " << bench.name << ": " << note << "\n";
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
            markDirectionalRepeats(scenes.back().settings);
        }
    }
    if (scenes.empty()) throw engine::InputError("no scene to sweep (give one with --scene)");
    return scenes;
}

std::vector<ShadowSetting> sweepSettings(const BenchOptions& options) {
    std::vector<ShadowSetting> settings;
    for (const std::string& variant : options.variants) {
        // One volume setting: it reads none of the map's settings, and the same picture
        // measured once per resolution, format and filter would be noise.
        if (!rendersMap(variant)) {
            settings.push_back({variant, 0, "", ""});
            continue;
        }
        for (int resolution : options.resolutions)
            for (const std::string& format : options.depthFormats)
                for (const std::string& filter : options.filters)
                    settings.push_back({variant, resolution, format, filter});
    }
    return expandAxes(settings, options);
}

std::vector<ShadowSetting> maskedSettings(const BenchOptions& options) {
    const auto preferred = [](const std::vector<std::string>& listed, const std::string& name) {
        return std::find(listed.begin(), listed.end(), name) != listed.end() ? name : listed.front();
    };
    // The plugin's default format and filter, when listed: what a scene gets unless it asks.
    const shadowmap::ShadowSettings defaults;
    std::vector<ShadowSetting> settings;
    for (const std::string& variant : options.variants) {
        if (!rendersMap(variant)) {
            settings.push_back({variant, 0, "", ""});
            continue;
        }
        for (int resolution : options.resolutions)
            settings.push_back({variant, resolution, preferred(options.depthFormats, shadowmap::toString(defaults.depthFormat)),
                                preferred(options.filters, shadowmap::toString(defaults.filter))});
    }
    return expandAxes(settings, options);
}

SweepRows runSweep(std::vector<BenchScene>& scenes, const engine::RendererConfig& rendererConfig,
                   const std::vector<engine::RenderPlugin*>& plugins, int frames, const RowCallback& onRow) {
    // Rows to come: a spot or point light's only where the setting is no directional repeat.
    int total = 0;
    for (const BenchScene& scene : scenes)
        for (const ShadowSetting& setting : scene.settings)
            for (int instance = 0; instance < scene.shadowedLights; ++instance)
                total += writesRowFor(setting, instanceLight(scene.scene, instance).type) ? 1 : 0;

    engine::Renderer renderer(rendererConfig, plugins);
    SweepRows sweep;
    std::vector<BenchRow>& rows = sweep.rows;
    for (BenchScene& scene : scenes) {
        if (scene.settings.empty()) continue;  // another shard's
        const std::vector<engine::Light> original = scene.scene.lights;
        evaluation::SettingTrial trial(renderer, scene.scene, {scene.camera}, frames);
        trial.setAreaTruth(true);
        trial.setNearDistance(scene.nearDistance);
        for (const ShadowSetting& setting : scene.settings) {
            applyToEveryLight(scene.scene, original, setting);
            const evaluation::TrialResult measured = trial.measure();
            const std::vector<evaluation::LightShimmer> shimmer = trial.shimmer(scene.shimmerPath);
            int jobRows = 0;
            for (const evaluation::LightResult& light : measured.lights) {
                // A spot or point light got the same as in an earlier job: its row is there.
                if (!writesRowFor(setting, instanceLight(scene.scene, light.slot).type)) continue;
                rows.push_back(makeRow(scene, setting, measured, light));
                for (const evaluation::LightShimmer& moving : shimmer)
                    if (moving.slot == light.slot) rows.back().shimmer = 100.0 * moving.count.fraction();
                onRow(rows.back(), static_cast<int>(rows.size()), total);
                ++jobRows;
            }
            sweep.jobRows.push_back(jobRows);
        }
    }
    return sweep;
}

} // namespace shadowmap_bench
