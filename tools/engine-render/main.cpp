// engine-render: renders one glTF scene headless (EGL surfaceless) and writes a PNG,
// optionally per-light shadow masks and truth masks, per-pass statistics and the compiled frame graph.
#include "AssetExtras.h"
#include "Median.h"
#include "ToolMain.h"
#include "DepthImage.h"
#include "LightTileImage.h"
#include "LightOverrides.h"
#include "RenderOptions.h"
#include "SceneLighting.h"
#include "AnimationPlayback.h"
#include "AutoExposure.h"

#include "ShadowEvaluation.h"

#include "truth/TexelDensityImage.h"

#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/Renderer.h"
#include "engine/scene/SceneEdit.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"
#include "engine/util/ProcessSetup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <numeric>

namespace {

// The light a command-line word names (a name, else its number in --list).
// The light instance a command-line word means. A name that several instances share (one
// light placed by two nodes, or a repeated name) is refused with their numbers, unless the
// option applies to all of them (`sharedNameSelectsAll`: --light sets every such instance).
int lightSlot(const engine::Scene& scene, const std::string& sceneFile, int renderedLights, const std::string& name,
              bool sharedNameSelectsAll = false) {
    const int slot = engine::findLightInstanceByNameOrNumber(scene, name);
    if (slot < 0)
        engine::throwInputError(sceneFile, "light \"" + name + "\"",
                                "no such light (" + engine::describeLightInstances(scene) + ")");
    std::string sharing;
    int shared = 0;
    for (int i = 0; i < static_cast<int>(scene.lightInstances.size()); ++i)
        if (engine::lightInstanceName(scene, i) == name) {
            sharing += (shared++ ? ", " : "") + std::to_string(i + 1);
        }
    if (shared > 1 && !sharedNameSelectsAll)
        engine::throwInputError(sceneFile, "light \"" + name + "\"",
                                "names " + std::to_string(shared) + " light instances (numbers " + sharing +
                                    "): choose one by its number (--list)");
    if (slot >= renderedLights)
        engine::throwInputError(sceneFile, "light \"" + name + "\"",
                                "only the first " + std::to_string(renderedLights) + " lights are rendered");
    return slot;
}

// Beyond --warmup, the most frames warm-up may add waiting for compilation to stop: the
// plan changes once (computing -> fetching cached shade), so 2 would do; 4 leaves room.
constexpr int kExtraWarmupFrames = 4;

struct PassSummary {
    std::vector<double> wallMs;  // of the frames it ran
    int framesRun = 0;           // a cached shadow map's pass is absent from later frames
    engine::PassReport last;
};

// A light's map time over the timed frames: the median, over the frames that drew its map
// (a volume light: its visibility), of its passes' time that frame (FrameResult::shadowPassMs).
// `rendered` is false when no timed frame drew it (served from the cache every time, e.g. a
// still light after warm-up, or the light has none); `frames` counts the timed frames that drew it.
struct MapTime {
    double ms = 0.0;
    bool rendered = false;
    int frames = 0;
};
using MapTimes = std::map<int, std::vector<double>>;  // light slot -> ms of each frame that drew its map
MapTime mapTime(const engine::ShadowView& view, const MapTimes& times) {
    const auto found = times.find(view.slot);
    if (found == times.end() || found->second.empty()) return {};
    return {tools::median(found->second), true, static_cast<int>(found->second.size())};
}

// Whether the light has a shadow whose passes have a time: a map, or a visibility per camera
// pixel (variant volume). Either is "cached" in a frame that kept it from the last.
bool hasShadowPasses(const engine::ShadowView& view) { return view.hasMap || view.hasScreenVisibility; }

// Why a light has no map this frame, for --shadow-map and --texel-density: a volume light
// never has one (its shadow is a visibility per camera pixel, which --shadow-mask writes).
std::string noMapReason(const engine::ShadowView* view) {
    if (view && view->hasScreenVisibility)
        return "variant volume has no shadow map (stenciled shadow volumes, exact per pixel: see --shadow-mask)";
    return "the light has no shadow map this frame (variant none, nothing in its frustum, or no shadow plugin)";
}

// engine::mapKindName for the printed table, which says how many cascades: "csm 3".
std::string mapLabel(const engine::ShadowView& view) {
    return view.cascadeSplits.empty() ? engine::mapKindName(view) : "csm " + std::to_string(view.layers.size());
}

nlohmann::json statsJson(const RenderOptions& options, const std::vector<double>& frameMs,
                         const std::vector<std::string>& order,
                         const std::map<std::string, PassSummary>& passes, const MapTimes& mapTimes,
                         const engine::FrameResult& last) {
    nlohmann::json stats;
    stats["scene"] = options.scene;
    stats["width"] = options.width;
    stats["height"] = options.height;
    stats["frames"] = options.frames;
    stats["frame_ms"] = frameMs;
    const tools::TimeSummary frameTimes = tools::summarizeTimes(frameMs);
    stats["frame_ms_median"] = frameTimes.median;
    stats["frame_ms_p99"] = frameTimes.p99;
    stats["frame_ms_max"] = frameTimes.max;
    nlohmann::json list = nlohmann::json::array();
    for (const std::string& name : order) {
        const PassSummary& pass = passes.at(name);
        list.push_back({{"name", name},
                        {"culled", pass.last.culled},
                        {"cull_reason", pass.last.cullReason},
                        {"order", pass.last.order},
                        {"frames_run", pass.framesRun},
                        {"wall_ms_median", tools::median(pass.wallMs)},
                        {"draws", pass.last.draws},
                        {"triangles", pass.last.triangles}});
    }
    stats["passes"] = list;
    // Per light, from the shadow views the plugin published: what scripts should read
    // rather than pass names, which may change.
    nlohmann::json maps = nlohmann::json::array();
    for (const engine::ShadowView& view : last.shadowViews) {
        const MapTime time = mapTime(view, mapTimes);
        maps.push_back({{"light", view.name}, {"slot", view.slot}, {"variant", view.variant},
                        {"map", engine::mapKindName(view)}, {"map_ms", time.rendered ? nlohmann::json(time.ms) : nlohmann::json(nullptr)},
                        {"map_cached", hasShadowPasses(view) && !time.rendered}, {"frames_rendered", time.frames}});
    }
    stats["shadow_maps"] = maps;
    stats["lit_instances_culled"] = last.litInstancesCulled;
    stats["plugins"] = last.pluginStats;
    return stats;
}

// A light with a size is also scored against the soft truth (the share of the light each
// pixel's point sees): the whole evaluation set, and its penumbra alone.
void printSoftErrors(const evaluation::LightResult& light, nlohmann::json& json) {
    const truth::ShadowErrors& soft = light.softErrors;
    const bool directional = light.view.angularDiameter > 0.0;
    std::printf("  %-20s against its size (%s %g): error %.3f %%, error-edge %.3f %%, penumbra error %.2f %% "
                "over %zu px\n",
                "", directional ? "angular_diameter" : "light_radius",
                directional ? light.view.angularDiameter : light.view.lightRadius, 100 * soft.error,
                100 * soft.errorNoEdge, 100 * soft.penumbraError, soft.evaluatedPenumbra);
    json["soft_error"] = 100 * soft.error;
    json["soft_error_noedge"] = 100 * soft.errorNoEdge;
    json["penumbra_error"] = 100 * soft.penumbraError;
    json["penumbra_pixels"] = soft.evaluatedPenumbra;
}

// Per shadowed light of `view` (ShadowEvaluator::evaluate): the median time of its map passes
// and its errors against ray-traced truth (docs/metrics.md, percent of the evaluation set),
// printed and returned for --stats.
nlohmann::json printLightErrors(const evaluation::ViewResult& view, const engine::Scene& scene,
                                const MapTimes& mapTimes) {
    std::printf("  %-20s %-9s %6s %9s %8s %8s %8s %12s %12s\n", "light", "variant", "map", "map ms",
                "acne %", "leak %", "error %", "error-edge %", "texel m");
    nlohmann::json lights = nlohmann::json::array();
    for (const evaluation::LightResult& light : view.lights) {
        // A map served from the cache in every timed frame has no time to report, and says so.
        const MapTime time = mapTime(light.view, mapTimes);
        const truth::ShadowErrors& e = light.errors;
        char shownTime[32];
        std::snprintf(shownTime, sizeof shownTime,
                      time.rendered ? "%.2f" : !hasShadowPasses(light.view) ? "-" : "cached", time.ms);
        // A texel's size on screen in pixels (docs/metrics.md), mean/p95; "-" where no pixel has one.
        const evaluation::TexelOnScreen& texel = light.texelOnScreen;
        char shownTexel[32] = "-";
        if (texel.count > 0) std::snprintf(shownTexel, sizeof shownTexel, "%.2f/%.2f", texel.mean, texel.p95);
        std::printf("  %-20s %-9s %6s %9s %8.3f %8.3f %8.3f %12.3f %12s\n", light.light.c_str(),
                    light.view.variant.c_str(), mapLabel(light.view).c_str(), shownTime, 100 * e.acne, 100 * e.leak,
                    100 * e.error, 100 * e.errorNoEdge, shownTexel);
        const auto texelFigure = [&](double value) { return texel.count > 0 ? nlohmann::json(value) : nlohmann::json(nullptr); };
        lights.push_back({{"light", light.light}, {"slot", light.slot}, {"variant", light.view.variant},
                          {"map_ms", time.rendered ? nlohmann::json(time.ms) : nlohmann::json(nullptr)},
                          {"map_cached", hasShadowPasses(light.view) && !time.rendered},
                          {"acne", 100 * e.acne}, {"leak", 100 * e.leak},
                          {"error", 100 * e.error}, {"error_noedge", 100 * e.errorNoEdge},
                          {"evaluated_pixels", e.evaluated},
                          {"texel_m_mean", texelFigure(texel.mean)}, {"texel_m_p95", texelFigure(texel.p95)}});
        if (light.softErrors.evaluated > 0) printSoftErrors(light, lights.back());
    }
    // A light that emits nothing casts no shadow to score: said, not scored.
    for (std::size_t slot = 0; slot < scene.lightInstances.size(); ++slot)
        if (!scene.lights[scene.lightInstances[slot].light].emitsLight())
            std::printf("  %-20s not scored: the light emits nothing (intensity or colour 0)\n",
                        engine::lightInstanceName(scene, static_cast<int>(slot)).c_str());
    return lights;
}

// A light's truth (LightResult::truth, 1 lit) as an 8-bit mask in --shadow-mask's encoding
// (255 lit, rounded as the GL writes a [0,1] value to RGBA8); pixels outside the evaluation
// set get the mask's background, 0 (the lit pass's light views clear to black), so the two
// PNGs line up pixel for pixel.
std::vector<std::uint8_t> truthMask8(const evaluation::LightResult& light) {
    std::vector<std::uint8_t> mask(light.truth.size(), 0);
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (light.evaluated[i])
            mask[i] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(light.truth[i], 0.0f, 1.0f)));
    return mask;
}

// --truth-mask: each named light's truth, from the evaluation that scored it. A light the
// evaluation did not score (variant none, or it emits nothing) has no truth to write.
void writeTruthMasks(const RenderOptions& options, const std::vector<int>& slots,
                     const evaluation::ViewResult& view) {
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const auto found = std::find_if(view.lights.begin(), view.lights.end(),
                                        [&](const evaluation::LightResult& light) { return light.slot == slots[i]; });
        if (found == view.lights.end())
            throw engine::InputError("--truth-mask " + options.truthMasks[i].first +
                                     ": the light is not scored (variant none, or it emits nothing)");
        engine::writePngAtomically(options.truthMasks[i].second, options.width, options.height, 1,
                                   truthMask8(*found));
    }
}

// --texel-density: per named light, m at every pixel of the last frame through that frame's
// map (the layer its lookup uses), over the light's evaluation set as --truth's texel m, as
// truth/TexelDensityImage.h's heat map. One surface capture serves every light.
void writeTexelDensities(const RenderOptions& options, const std::vector<int>& slots, const engine::Scene& scene,
                         engine::Renderer& renderer, const engine::FrameResult& last,
                         const engine::FrameCamera& camera) {
    if (slots.empty()) return;
    const truth::SurfaceBuffer surfaces = truth::SurfaceCapture().capture(scene, renderer.gpu(), camera);
    std::printf("  texel density: %s\n", truth::texelDensityLegend().c_str());
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const auto& [light, file] = options.texelDensities[i];
        const engine::ShadowView* view = last.shadowView(slots[i]);
        if (!view || !view->hasMap) throw engine::InputError("--texel-density " + light + ": " + noMapReason(view));
        const std::vector<double> m =
            truth::texelOnScreenImage(*view, surfaces, truth::evaluationSet(scene, slots[i], surfaces));
        engine::writePngAtomically(file, options.width, options.height, 4, truth::texelDensityImage(m));
        const auto valued = std::count_if(m.begin(), m.end(), [](double value) { return std::isfinite(value); });
        std::printf("  texel density of %s: %s (%td of %zu pixels with a value)\n", light.c_str(), file.c_str(),
                    valued, m.size());
    }
}

// More than this share of saturated pixels is "most of the image".
constexpr double kMostlySaturated = 0.5;

// The share of RGBA8 pixels with a colour channel at 255.
double saturatedFraction(const std::vector<std::uint8_t>& rgba) {
    std::size_t saturated = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        saturated += rgba[i] == 255 || rgba[i + 1] == 255 || rgba[i + 2] == 255;
    return rgba.empty() ? 0.0 : static_cast<double>(saturated) / static_cast<double>(rgba.size() / 4);
}

// --list: the scene's cameras and lights with the numbers and names the options accept.
void printCamerasAndLights(const engine::Scene& scene, const std::string& sceneFile) {
    std::printf("%s\n  cameras (--camera NAME or number; none: a framing camera)\n", sceneFile.c_str());
    for (std::size_t i = 0; i < scene.cameraInstances.size(); ++i)
        std::printf("  %4zu  %-28s %s\n", i + 1, engine::cameraInstanceName(scene, static_cast<int>(i)).c_str(),
                    engine::toString(scene.cameras[scene.cameraInstances[i].camera].type));
    if (scene.cameraInstances.empty()) std::printf("        (none)\n");
    std::printf("  lights (--light NAME=VARIANT and the other per-light options: name or number)\n");
    for (std::size_t i = 0; i < scene.lightInstances.size(); ++i)
        std::printf("  %4zu  %-28s %s\n", i + 1, engine::lightInstanceName(scene, static_cast<int>(i)).c_str(),
                    engine::toString(scene.lights[scene.lightInstances[i].light].type));
    if (scene.lightInstances.empty()) std::printf("        (none: --key-light adds one)\n");
}

// `context` and `host` live in main(), outside the try block that reports errors: an
// exception thrown by plugin code must be read before the plugin is unloaded, and the
// plugin's GL objects must be deleted while the context still exists (host first).
int run(const RenderOptions& options, std::unique_ptr<engine::GlContext>& context,
        engine::PluginHost& host) {
    engine::tuneAllocatorForRendering();
    // Every output is checked before the scene loads: a run never ends, after its rendering,
    // in a file it cannot write.
    if (!options.list)
        for (const std::string& file : outputFiles(options)) engine::checkOutputPath(file);
    std::vector<std::string> warnings;
    engine::Scene scene = engine::loadGltf(options.scene, &warnings);
    for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
    const tools::StagedScene staged = tools::stageScene(scene, options.scene, options.lighting);
    if (options.list) {
        printCamerasAndLights(scene, options.scene);
        return 0;
    }
    for (const std::string& note : staged.notes) std::printf("%s\n", note.c_str());
    // Settings the tuner chose for a picture of another size may not be the best for this one.
    if (const auto tuned = tools::readTunedSize(options.scene);
        tuned && tools::farFromTunedSize(*tuned, options.width, options.height))
        std::cerr << "note: " << options.scene << "'s shadow settings were tuned at " << tuned->width << "x"
                  << tuned->height << " (asset.extras.shadowmap_tune), this picture is " << options.width << "x"
                  << options.height << ": shadowmap-tune --width " << options.width << " --height " << options.height
                  << " chooses for it\n";
    for (const std::string& warning : staged.warnings) std::cerr << "warning: " << warning << "\n";

    engine::EngineConfig config = engine::loadEngineConfig(options.config);
    tools::applySettingOverrides(config, options.pluginSettings);
    if (options.exposureEv100) config.renderer.exposure = engine::exposureFromEv100(*options.exposureEv100);
    if (options.msaa) config.renderer.msaa = *options.msaa;
    const int renderedLights = engine::renderedLightCount(config.renderer.clusteredLights, scene.lightInstances.size());
    context = engine::createEglContext();
    context->makeCurrent();

    host.loadAll(config);
    const auto plugins = host.renderPlugins();
    // Plugins know lights by the name the scene gives them, not by what was typed; a shared
    // name sets every instance of it.
    const std::vector<tools::LightOverride> lightSettings =
        tools::resolveLightOverrides(options.lightSettings, [&](const std::string& light) {
            return engine::lightInstanceName(scene, lightSlot(scene, options.scene, renderedLights, light, true));
        });
    // A light's intensity and color are the scene's (the lit pass reads them), the rest the plugins'.
    std::vector<std::string> propertyWarnings;
    const std::vector<tools::LightOverride> shadowSettings =
        tools::applyLightProperties(scene, lightSettings, propertyWarnings);
    for (const std::string& warning : propertyWarnings) std::cerr << "warning: " << warning << "\n";
    tools::applyLightOverrides(shadowSettings, plugins, options.config);
    for (const std::string& warning : tools::shadowedSettingWarnings(options.pluginSettings, lightSettings, host, scene))
        std::cerr << "warning: " << warning << "\n";
    tools::AnimationPlayback playback;
    if (!options.animate.empty() || options.time) {
        playback.animations = tools::selectAnimations(scene, options.scene, options.animate.empty() ? "--time" : "--animate",
                                                      options.animate.empty() ? "all" : options.animate);
        playback.startSeconds = options.time.value_or(0.0);
        playback.fps = options.fps.value_or(playback.fps);
        playback.animating = !options.animate.empty();
        if (playback.animations.empty()) std::cerr << "warning: --time: " << options.scene << " has no animations\n";
        tools::poseScene(scene, playback, playback.secondsAtFrame(0));
    }
    const int orbitingSlot = options.orbitLight.empty() ? -1 : lightSlot(scene, options.scene, renderedLights, options.orbitLight);
    const int orbitingLight = orbitingSlot < 0 ? -1 : scene.lightInstances[orbitingSlot].node;
    const glm::dvec3 orbitCenter = scene.worldBounds.empty() ? glm::dvec3(0.0) : scene.worldBounds.center();
    constexpr double kOrbitStep = 0.034906585039886591;  // 2 degrees per frame: deterministic

    engine::FrameRequest request;
    const int cameraInstance = engine::chooseCameraInstance(scene, options.camera, options.scene);
    request.camera = cameraInstance < 0 ? engine::framingCamera(scene, options.width, options.height)
                                        : engine::cameraFromScene(scene, cameraInstance, options.width, options.height);
    // --exposure auto: metered once, on the first frame, before the renderer that draws every
    // frame is made with it. One exposure for the whole run: frames of an orbit or an
    // animation compare as they are (no flicker, nothing adapting behind the numbers).
    if (options.autoExposure) {
        const tools::AutoExposure chosen = tools::chooseAutoExposure(config.renderer, plugins, scene, request.camera);
        config.renderer.exposure = chosen.exposure;
        std::printf("%s\n", tools::describe(chosen).c_str());
    }
    engine::Renderer renderer(config.renderer, plugins);
    renderer.setScene(scene);
    request.timing = true;
    for (const auto& [light, file] : options.shadowMasks)
        request.shadowMaskSlots.push_back(lightSlot(scene, options.scene, renderedLights, light));
    for (const auto& [light, file] : options.comparisons)
        request.comparisonSlots.push_back(lightSlot(scene, options.scene, renderedLights, light));

    for (const auto& [light, file] : options.shadowMaps)
        request.shadowMapSlots.push_back(lightSlot(scene, options.scene, renderedLights, light));
    // Resolved before rendering, so a bad name costs no frames.
    std::vector<int> truthMaskSlots;
    for (const auto& [light, file] : options.truthMasks)
        truthMaskSlots.push_back(lightSlot(scene, options.scene, renderedLights, light));
    std::vector<int> texelDensitySlots;
    for (const auto& [light, file] : options.texelDensities)
        texelDensitySlots.push_back(lightSlot(scene, options.scene, renderedLights, light));

    std::vector<double> frameMs;
    std::vector<std::string> order;
    std::map<std::string, PassSummary> passes;
    MapTimes mapTimes;
    engine::FrameResult last;
    nlohmann::json shadeCacheFrames = nlohmann::json::array();  // per timed frame
    int framesComputingShade = 0;  // timed frames whose lit pass recomputed a cacheable light
    int framesLimitingLookups = 0;  // timed frames that looked some light up only in its footprint
    std::vector<int> programsLinked;  // per timed frame: each one waited for the shader compiler
    // Untimed: at least --warmup frames, then until a frame compiles nothing new (the shade
    // cache's fetching programs appear in the second frame), so the first timed frame times
    // rendering, not shader compilation. --warmup 0 times the cold start.
    // With something to move, warm-up also compiles what the first moving frames need. An
    // animation may move the casters (every light's shade changes) and any light.
    engine::ExpectedMotion motion;
    motion.cameraOrGeometry = options.orbitCamera || playback.animating;
    if (orbitingSlot >= 0) motion.lights.push_back(orbitingSlot);
    if (playback.animating)
        for (int slot = 0; slot < static_cast<int>(scene.lightInstances.size()); ++slot) motion.lights.push_back(slot);
    if (options.warmup > 0) renderer.warmUp(request, options.warmup, options.warmup + kExtraWarmupFrames, motion);
    for (int frame = 0; frame < options.frames; ++frame) {
        if (frame > 0 && playback.animating) {
            tools::poseScene(scene, playback, playback.secondsAtFrame(frame));
            // A glTF camera is followed as its node animates (--orbit-camera moves it instead).
            if (cameraInstance >= 0 && !options.orbitCamera)
                request.camera = engine::cameraFromScene(scene, cameraInstance, options.width, options.height);
        }
        if (frame > 0 && orbitingLight >= 0) engine::orbitNode(scene, orbitingLight, orbitCenter, kOrbitStep);
        if (frame > 0 && options.orbitCamera)
            request.camera.eyeToWorld = engine::orbitTransform(request.camera.eyeToWorld, orbitCenter, kOrbitStep);
        last = renderer.renderFrame(request);
        frameMs.push_back(last.frameMs);
        programsLinked.push_back(last.programsLinked);
        shadeCacheFrames.push_back(last.shadeCache.toJson());
        framesLimitingLookups += last.footprintLimitedLights.empty() ? 0 : 1;
        framesComputingShade += last.shadeCache.recomputed() ? 1 : 0;
        for (const engine::PassReport& report : last.passes) {
            auto [it, inserted] = passes.try_emplace(report.name);
            if (inserted) order.push_back(report.name);
            if (!report.culled) it->second.wallMs.push_back(report.wallMs);
            it->second.framesRun += report.culled ? 0 : 1;
            it->second.last = report;
        }
        for (const engine::ShadowView& view : last.shadowViews) {
            bool ran = false;
            const double ms = last.shadowPassMs(view, ran);
            if (ran) mapTimes[view.slot].push_back(ms);
        }
    }
    if ((!options.shadowMasks.empty() || !options.comparisons.empty()) && !last.shadowTermProvided)
        throw engine::InputError(std::string(options.shadowMasks.empty() ? "--shadow-compare" : "--shadow-mask") +
                                 ": no loaded plugin provides a shadow term (config " + options.config + ")");

    const std::vector<std::uint8_t> image = renderer.readColor();
    // Most of the picture white: lights in physical units (Blender 4 writes candela and lux)
    // rendered at display exposure. Said, with the way out.
    if (const double saturated = saturatedFraction(image); saturated > kMostlySaturated)
        std::fprintf(stderr,
                     "warning: %.0f%% of the image is saturated: the lights may be in physical units (candela, "
                     "lux); try --exposure auto, or --exposure EV100 (a sunlit scene 15, an office 8)\n",
                     100.0 * saturated);
    engine::writePngAtomically(options.out, options.width, options.height, 4, image);
    for (std::size_t i = 0; i < options.shadowMasks.size(); ++i)
        engine::writePngAtomically(options.shadowMasks[i].second, options.width, options.height, 1,
                                   renderer.readShadowMask(request.shadowMaskSlots[i]));
    for (std::size_t i = 0; i < options.comparisons.size(); ++i)
        engine::writePngAtomically(options.comparisons[i].second, options.width, options.height, 4,
                                   renderer.readComparison(request.comparisonSlots[i]));
    for (std::size_t i = 0; i < options.shadowMaps.size(); ++i) {
        const auto& [light, file] = options.shadowMaps[i];
        const auto found = last.shadowMaps.find(request.shadowMapSlots[i]);
        if (found == last.shadowMaps.end())
            throw engine::InputError("--shadow-map " + light + ": " +
                                     noMapReason(last.shadowView(request.shadowMapSlots[i])));
        int width = 0, height = 0;
        auto gray = depthToGray(found->second, width, height);
        if (found->second.cube) labelCubeFaces(gray, width, height, found->second.width);
        engine::writePngAtomically(file, width, height, 1, gray);
    }

    if (!options.lightTiles.empty()) {
        if (!last.clusteredLights)
            throw engine::InputError("--light-tiles " + options.lightTiles +
                                     ": the frame was not shaded by the clustered lit pass (32 lights or fewer; "
                                     "\"renderer\": {\"clustered_lights\": true} in the engine config forces it)");
        engine::writePngAtomically(options.lightTiles, options.width, options.height, 4,
                                   tools::lightTileImage(last.tileLightCounts, last.tileColumns, engine::kLightTileSize,
                                                         options.width, options.height));
        std::printf("  light tiles: %s (%s)\n", options.lightTiles.c_str(), tools::lightTileLegend().c_str());
    }
    const tools::TimeSummary frameTimes = tools::summarizeTimes(frameMs);
    std::printf("%s: %dx%d, %d frame(s), median frame %.2f ms, p99 %.2f ms, max %.2f ms (%s)\n",
                options.scene.c_str(), options.width, options.height, options.frames, frameTimes.median,
                frameTimes.p99, frameTimes.max, context->rendererString().c_str());
    std::printf("  %-28s %10s %8s %12s  %s\n", "pass", "ms", "draws", "triangles", "state");
    for (const std::string& name : order) {
        const PassSummary& pass = passes[name];
        const std::string state = pass.last.culled ? "culled: " + pass.last.cullReason
                                  : "ran in " + std::to_string(pass.framesRun) + " of " +
                                        std::to_string(options.frames) + " frames";
        std::printf("  %-28s %10.2f %8llu %12llu  %s\n", name.c_str(), tools::median(pass.wallMs),
                    static_cast<unsigned long long>(pass.last.draws),
                    static_cast<unsigned long long>(pass.last.triangles), state.c_str());
    }
    const nlohmann::json shadeCache = last.shadeCache.toJson();
    if (last.shadeCache.layers > 0)
        std::printf("  shade cache: last frame fetched lights %s, computed %s, moving %s, uncached %s; "
                    "lights recomputed in %d of %d frames\n",
                    shadeCache["fetched"].dump().c_str(), shadeCache["computed"].dump().c_str(),
                    shadeCache["moving"].dump().c_str(), shadeCache["uncached"].dump().c_str(),
                    framesComputingShade, options.frames);
    if (framesLimitingLookups > 0)
        std::printf("  light footprints: last frame looked lights %s up only in their footprints (lit pass in "
                    "%d regions); lookups limited in %d of %d frames\n",
                    nlohmann::json(last.footprintLimitedLights).dump().c_str(), last.shadingRegions,
                    framesLimitingLookups, options.frames);
    const int linkedAfterWarmUp = std::accumulate(programsLinked.begin(), programsLinked.end(), 0);
    if (linkedAfterWarmUp > 0) {
        int framesLinking = 0;
        for (const int linked : programsLinked) framesLinking += linked > 0 ? 1 : 0;
        std::printf("  shader programs: %d linked after warm-up, in %d of %d timed frames\n", linkedAfterWarmUp,
                    framesLinking, options.frames);
    }
    nlohmann::json stats = statsJson(options, frameMs, order, passes, mapTimes, last);
    stats["shade_cache"] = shadeCacheFrames;
    stats["programs_linked"] = programsLinked;
    // The clustered lit pass's last tile lists (engine/render/LightTiles.h).
    if (last.clusteredLights)
        stats["light_tiles"] = {{"entries", last.tileListEntries}, {"longest", last.longestTileList}};
    const engine::RendererSwitches& switches = renderer.switches();
    stats["renderer_switches"] = {{"shade_cache", switches.shadeCache},
                                  {"light_footprints", switches.lightFootprints},
                                  {"unrolled_light_sum", switches.unrolledLightSum}};
    writeTexelDensities(options, texelDensitySlots, scene, renderer, last, request.camera);
    if (options.truth) {
        evaluation::ShadowEvaluator evaluator(renderer, scene);
        evaluator.setKeepTruth(!options.truthMasks.empty());
        const evaluation::ViewResult view = evaluator.evaluate(request.camera, 0);
        stats["lights"] = printLightErrors(view, scene, mapTimes);
        writeTruthMasks(options, truthMaskSlots, view);
    }
    if (!options.stats.empty()) engine::writeFileAtomically(options.stats, stats.dump(2));
    if (!options.graphDot.empty()) engine::writeFileAtomically(options.graphDot, last.graphviz);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return tools::toolMain("engine-render", kRenderUsage, argc, argv, parseRenderOptions,
                           [](const auto& options, tools::ToolSession& session) {
                               return run(options, session.context, session.host);
                           });
}
