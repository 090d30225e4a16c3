// shadowmap-stress: finds where each shadow variant breaks numerically. Generates scenes
// (StressScenes.h), sweeps distance from the origin, light near/far ratio, light elevation,
// whole-scene scale and special cases (Sweeps.h) for every variant and depth format, and
// measures each case against Embree ray-traced truth (tools/evaluation). Writes a CSV, a
// plot per sweep and a summary with a pass/fail table (Report.h).
//
// Exit status: 0 every bound holds, 2 some bound failed, 1 bad input or an error.
#include "CommandLine.h"
#include "OptionValues.h"
#include "SettingOverrides.h"
#include "ToolMain.h"
#include "Report.h"
#include "StressScenes.h"
#include "Sweeps.h"

#include "CameraPath.h"
#include "ShadowEvaluation.h"

#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"
#include "engine/util/ProcessSetup.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

namespace {

constexpr const char* kUsage =
    "usage: shadowmap-stress --out DIR [options]\n"
    "  --out DIR              write DIR/stress.csv, DIR/<sweep>.png, DIR/summary.md\n"
    "  --quick                the small CI version (96x64 view, 512 maps, few points)\n"
    "  --sweep NAME           only this sweep (repeatable): distance, near_far, elevation,\n"
    "                         scale, shimmer, special (and distance_skinned, distance_baked)\n"
    "  --variants LIST        comma-separated (default standard,woo,backface,volume)\n"
    "  --formats LIST         comma-separated among d16,d24,d32f,d32f_rz (d32f with\n"
    "                         reversed Z); default all four, quick: d24,d32f,d32f_rz;\n"
    "                         volume renders no map: one row per case, format empty\n"
    "  --width W --height H   view size (default 320x240; quick 96x64)\n"
    "  --resolution N         shadow map texels per side (default 1024; quick 512)\n"
    "  --config FILE          engine config (default: shadowmap_plugin with its defaults)\n"
    "  --set PLUGIN.KEY=JSON  override a plugin setting of the config (repeatable)\n"
    "  --no-plots             skip gnuplot\n"
    "  --images               also write DIR/images/<case>.png per case: the view in grey,\n"
    "                         red = acne (truth lit, shadowed), blue = leak (truth shadowed,\n"
    "                         lit), dark = outside the evaluation set\n"
    "exit status: 0 all bounds hold, 2 a bound failed, 1 bad input or error\n";

struct Options {
    std::filesystem::path out;
    bool quick = false;
    std::vector<std::string> sweeps;
    std::vector<std::string> variants;
    std::vector<std::string> formats;
    int width = 0, height = 0, resolution = 0;  // 0: the mode's default
    std::string config;
    std::vector<tools::SettingOverride> pluginSettings;
    bool plots = true;
    bool images = false;
    bool help = false;
    std::string commandLine;
};

// Bounds of typos, not of the GL: the plugin checks the GL's own texture size limit.
constexpr int kMaxSize = 16384, kMaxResolution = 65536;

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 0; i < argc; ++i) {
        if (i) options.commandLine += ' ';
        options.commandLine += argv[i];
    }
    options.help = tools::parseFlags(argc, argv, {"--quick", "--no-plots", "--images"},
                                     [&](const std::string& flag, const std::string& value) {
        if (flag == "--out") options.out = value;
        else if (flag == "--quick") options.quick = true;
        else if (flag == "--sweep") options.sweeps.push_back(value);
        else if (flag == "--variants") options.variants = tools::parseList(flag, value);
        else if (flag == "--formats") options.formats = tools::parseList(flag, value);
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--resolution") options.resolution = tools::parseInteger(flag, value, 1, kMaxResolution);
        else if (flag == "--config") options.config = value;
        else if (flag == "--no-plots") options.plots = false;
        else if (flag == "--images") options.images = true;
        else if (flag == "--set") tools::addSettingOverride(options.pluginSettings, flag, value);
        else return false;
        return true;
    });
    if (options.help) return options;
    if (options.out.empty()) throw std::invalid_argument("--out DIR is required");
    if (!options.width) options.width = options.quick ? 96 : 320;
    if (!options.height) options.height = options.quick ? 64 : 240;
    if (!options.resolution) options.resolution = options.quick ? 512 : 1024;
    return options;
}

engine::EngineConfig makeConfig(const Options& options) {
    engine::EngineConfig config;
    if (!options.config.empty()) {
        config = engine::loadEngineConfig(options.config);
    } else {
        config.sourcePath = "shadowmap-stress built-in config";
        config.plugins.push_back({shadowmap::kPluginName, nlohmann::json::object()});
    }
    tools::applySettingOverrides(config, options.pluginSettings);
    return config;
}

// Everything the plugin published about the light's matrices must be finite (far may be
// +infinity: an infinite far plane).
bool viewFinite(const engine::ShadowView& view) {
    if (!std::isfinite(view.nearPlane) || std::isnan(view.farPlane)) return false;
    for (const engine::ShadowMapLayer& layer : view.layers)
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row)
                if (!std::isfinite(layer.lightToWorld[column][row]) || !std::isfinite(layer.projection[column][row]))
                    return false;
    return true;
}

// The case as a picture: grey where the shade agrees with the truth (brighter = lit), red
// where the map shadows a lit pixel (acne), blue where it lights a shadowed one (leak), dark
// outside the evaluation set. Recomputes the truth (cheap at these sizes).
void writeErrorImage(const std::filesystem::path& path, engine::Renderer& renderer, const engine::Scene& scene,
                     const engine::FrameCamera& camera) {
    const std::vector<std::uint8_t> mask = renderer.readShadowMask(0);
    if (mask.empty()) return;
    truth::SurfaceCapture capture;
    const truth::SurfaceBuffer surfaces = capture.capture(scene, renderer.gpu(), camera);
    const auto visible = truth::visibility(scene, 0, surfaces);
    const auto inSet = truth::evaluationSet(scene, 0, surfaces);
    std::vector<std::uint8_t> rgb(surfaces.pixelCount() * 3, 0);
    for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
        std::uint8_t* p = &rgb[3 * i];
        const bool lit = mask[i] >= 128;
        if (!surfaces.covered[i]) continue;
        if (!inSet[i]) { p[0] = p[1] = p[2] = 40; continue; }
        if (lit == (visible[i] != 0)) { p[0] = p[1] = p[2] = lit ? 200 : 110; continue; }
        if (visible[i]) { p[0] = 230; p[1] = 30; p[2] = 30; }  // acne
        else { p[0] = 40; p[1] = 80; p[2] = 255; }             // leak
    }
    engine::writePngAtomically(path, camera.width, camera.height, 3, rgb);
}

// The first layer of a depth map, stretched over its own range of drawn depths (white =
// far / nothing drawn).
void writeDepthImage(const std::filesystem::path& path, const engine::DepthReadback& map) {
    const std::size_t count = static_cast<std::size_t>(map.width) * map.height;
    float lo = 1e30f, hi = -1e30f;
    for (std::size_t i = 0; i < count; ++i)
        if (std::isfinite(map.depth[i]) && map.depth[i] > 0.0f && map.depth[i] < 1.0f) {
            lo = std::min(lo, map.depth[i]);
            hi = std::max(hi, map.depth[i]);
        }
    std::vector<std::uint8_t> gray(count, 255);
    for (std::size_t i = 0; i < count; ++i)
        if (map.depth[i] > 0.0f && map.depth[i] < 1.0f && hi > lo)
            gray[i] = static_cast<std::uint8_t>(250.0f * (map.depth[i] - lo) / (hi - lo));
    engine::writePngAtomically(path, map.width, map.height, 1, gray);
}

// The row's errors in percent: against the binary truth, and for a light with a size
// (evaluated soft pixels) against the soft truth too.
void fillErrors(stress::Row& row, const evaluation::LightResult& result) {
    row.acne = 100.0 * result.errors.acne;
    row.leak = 100.0 * result.errors.leak;
    row.error = 100.0 * result.errors.error;
    row.errorNoEdge = 100.0 * result.errors.errorNoEdge;
    row.evaluated = result.errors.evaluated;
    row.nonFiniteShade = result.nonFinitePixels;
    if (result.softErrors.evaluated > 0)
        row.soft = stress::Row::SoftErrors{100.0 * result.softErrors.error, 100.0 * result.softErrors.errorNoEdge,
                                           100.0 * result.softErrors.penumbraError};
}

// "  soft 0.412%  penumbra 8.100%" for a light with a size, "" otherwise.
std::string softText(const stress::Row& row) {
    if (!row.soft) return {};
    char text[96];
    std::snprintf(text, sizeof text, "  soft %7.3f%%  penumbra %7.3f%%", row.soft->error, row.soft->penumbraError);
    return text;
}

struct Runner {
    const Options& options;
    std::vector<engine::RenderPlugin*> plugins;
    engine::RendererConfig rendererConfig;
    std::vector<std::string> variants;
    std::vector<stress::FormatSetting> formats;
    std::vector<stress::Row> rows;

    void runPoint(const stress::Sweep& sweep, const stress::SweepPoint& point, stress::LightKind light) {
        stress::SceneSpec spec = point.spec;
        spec.light = light;
        stress::StressScene built = stress::buildStressScene(spec, options.width, options.height);
        const nlohmann::json baseShadow = built.scene.lights[0].extras["shadow"];
        engine::Renderer renderer(rendererConfig, plugins);
        renderer.setScene(built.scene);
        evaluation::ShadowEvaluator evaluator(renderer, built.scene);
        for (const std::string& variant : variants)
            for (const stress::FormatSetting& format : stress::formatsFor(variant, formats)) {
                const auto start = std::chrono::steady_clock::now();
                nlohmann::json shadow = baseShadow;
                shadow.update(format.settings);
                shadow["variant"] = variant;
                // Volume reads no resolution, but its standard-map fallback (among
                // alpha-tested casters) does: the same map size as the other rows.
                shadow["resolution"] = options.resolution;
                built.scene.lights[0].extras["shadow"] = shadow;
                // Only the light's settings changed: the plugin re-reads them and re-renders
                // the map if they changed it, without uploading the scene again.
                renderer.reloadSettings();

                const evaluation::ViewResult view = evaluator.evaluate(built.camera, 0);
                engine::FrameRequest request;
                request.camera = built.camera;
                request.shadowMapSlots = {0};
                request.shadowMaskSlots = {0};  // keeps the mask current for --images
                const engine::FrameResult frame = renderer.renderFrame(request);
                const engine::ShadowView* published = frame.shadowView(0);
                if (!published) throw std::runtime_error("the shadow plugin published no view of the light");

                stress::Row row;
                row.sweep = sweep.name;
                row.light = stress::toString(light);
                row.variant = variant;
                row.format = format.name;
                row.label = point.label;
                row.value = point.value;
                row.map = engine::mapKindName(*published);
                row.skipReason = published->skipReason;
                if (published->hasMap) {
                    row.nearPlane = published->nearPlane;
                    row.farPlane = std::isinf(published->farPlane) ? -1.0 : published->farPlane;
                }
                row.nonFiniteStats = !viewFinite(*published);
                if (!view.lights.empty()) fillErrors(row, view.lights.front());
                if (const auto found = frame.shadowMaps.find(0); found != frame.shadowMaps.end())
                    for (float depth : found->second.depth) row.nonFiniteDepth += !std::isfinite(depth);
                if (point.shimmerFrames > 0)
                    for (const evaluation::LightShimmer& moving :
                         evaluator.shimmer(evaluation::onePixelPan(built.camera, point.shimmerFrames)))
                        if (moving.slot == 0) row.shimmer = 100.0 * moving.count.fraction();
                if (options.images) {
                    const std::string name = row.sweep + "_" + row.label + "_" + row.light + "_" + row.variant +
                                             (row.format.empty() ? "" : "_" + row.format);
                    std::filesystem::create_directories(options.out / "images");
                    writeErrorImage(options.out / "images" / (name + ".png"), renderer, built.scene, built.camera);
                    if (const auto found = frame.shadowMaps.find(0); found != frame.shadowMaps.end())
                        writeDepthImage(options.out / "images" / (name + "_map.png"), found->second);
                }
                row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::printf("  %-9s %-17s %-11s %-8s %-7s error %7.3f%%  no-edge %7.3f%%  acne %7.3f%%  leak %7.3f%%%s%s%s\n",
                            row.sweep.c_str(), row.label.c_str(), row.light.c_str(), row.variant.c_str(),
                            row.format.c_str(), row.error, row.errorNoEdge, row.acne, row.leak,
                            softText(row).c_str(), row.map == "none" ? "  NO MAP: " : "",
                            row.map == "none" ? row.skipReason.c_str() : "");
                std::fflush(stdout);
                rows.push_back(std::move(row));
            }
    }
};

int run(const Options& options, std::unique_ptr<engine::GlContext>& context, engine::PluginHost& host) {
    const auto start = std::chrono::steady_clock::now();
    engine::tuneAllocatorForRendering();

    // Which sweeps, variants and formats.
    std::vector<stress::Sweep> sweeps = stress::makeSweeps(options.quick);
    if (!options.sweeps.empty()) {
        std::vector<stress::Sweep> chosen;
        for (const std::string& name : options.sweeps) {
            const auto found = std::find_if(sweeps.begin(), sweeps.end(),
                                            [&](const stress::Sweep& s) { return s.name == name; });
            if (found == sweeps.end()) throw engine::InputError("--sweep " + name + ": no such sweep in this mode");
            chosen.push_back(*found);
        }
        sweeps = chosen;
    }
    std::vector<stress::FormatSetting> formats = stress::defaultFormats(options.quick);
    if (!options.formats.empty()) {
        formats.clear();
        const auto known = stress::knownFormats();
        for (const std::string& name : options.formats) {
            const auto found = std::find_if(known.begin(), known.end(),
                                            [&](const stress::FormatSetting& f) { return f.name == name; });
            if (found == known.end()) throw engine::InputError("--formats: unknown format \"" + name + "\"");
            formats.push_back(*found);
        }
    }
    std::vector<std::string> variants = options.variants.empty() ? stress::defaultVariants() : options.variants;
    // A misspelt variant is refused here, by the plugin's own parser, before any rendering.
    for (const std::string& variant : variants) shadowmap::parseVariant(variant, "--variants", "");

    const engine::EngineConfig config = makeConfig(options);
    context = engine::createEglContext();
    context->makeCurrent();
    host.loadAll(config);

    Runner runner{options, host.renderPlugins(), config.renderer, variants, formats, {}};
    for (const stress::Sweep& sweep : sweeps) {
        std::printf("sweep %s: %s\n", sweep.name.c_str(), sweep.title.c_str());
        for (const stress::SweepPoint& point : sweep.points)
            for (stress::LightKind light : point.lights.empty() ? sweep.lights : point.lights)
                runner.runPoint(sweep, point, light);
    }

    std::filesystem::create_directories(options.out);
    const std::vector<stress::BoundResult> bounds = stress::checkBounds(runner.rows);
    stress::writeCsv(options.out / "stress.csv", runner.rows);
    std::string warning;
    const bool plots = options.plots && stress::writePlots(options.out, sweeps, runner.rows, warning);
    if (!warning.empty()) std::fprintf(stderr, "shadowmap-stress: warning: %s\n", warning.c_str());

    stress::RunInfo info;
    info.commandLine = options.commandLine;
    info.machine = stress::describeMachine();
    info.glRenderer = context->rendererString();
    info.width = options.width;
    info.height = options.height;
    info.resolution = options.resolution;
    info.quick = options.quick;
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stress::writeSummary(options.out / "summary.md", info, sweeps, runner.rows, bounds, plots);

    int failed = 0;
    std::printf("\n%-14s %-8s %7s  %s\n", "bound", "result", "checked", "worst case");
    for (const stress::BoundResult& bound : bounds) {
        std::printf("%-14s %-8s %7d  %s\n", bound.name.c_str(),
                    bound.checked == 0 ? "not run" : bound.pass() ? "pass" : "FAIL", bound.checked,
                    bound.worst.c_str());
        for (std::size_t i = 0; i < bound.failures.size() && i < 5; ++i)
            std::printf("    %s\n", bound.failures[i].c_str());
        failed += bound.pass() ? 0 : 1;
    }
    std::printf("%zu cases in %.1f s (%s); results in %s\n", runner.rows.size(), info.seconds,
                info.machine.c_str(), options.out.string().c_str());
    return failed ? 2 : 0;
}

} // namespace

int main(int argc, char** argv) {
    return tools::toolMain("shadowmap-stress", kUsage, argc, argv, parseOptions,
                           [](const auto& options, tools::ToolSession& session) {
                               return run(options, session.context, session.host);
                           });
}
