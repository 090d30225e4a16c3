#include "RenderOptions.h"

#include "AnimationPlayback.h"
#include "AutoExposure.h"
#include "CommandLine.h"
#include "OptionValues.h"

#include "engine/config/EngineConfig.h"

#include <cctype>
#include <filesystem>
#include <stdexcept>

const char* const kRenderUsage =
    "usage: engine-render [--config CONFIG.json] --scene SCENE.gltf|.glb --out OUT.png\n"
    "       engine-render --scene SCENE.gltf|.glb --list   (its cameras and lights, numbered)\n"
    "  [--width W] [--height H] [--camera NAME|NUMBER|framing]\n"
    "  (a light or camera is named by its name, its node's name, or its number in --list)\n"
    "  [--light-set NAME.KEY=JSON]...  (a per-light setting: wins over the light's glTF extras;\n"
    "                                    NAME.intensity=I (>= 0; lux for a directional light, else\n"
    "                                    candela) and NAME.color=[r,g,b] replace the light's own)\n"
    "  [--light NAME=VARIANT]...        (--light-set NAME.variant=VARIANT)\n"
    "  [--shadow-mask NAME=MASK.png]... [--shadow-map NAME=MAP.png]...\n"
    "  [--shadow-compare NAME=VIEW.png]...  (green: r agrees with the map, red: shadowed)\n"
    "  [--light-tiles HEAT.png]  (the clustered lit pass's tiles coloured by the lights each lists:\n"
    "               black 0, blue 1, green 4, yellow 16, red 64 or more; docs/many-lights.md)\n"
    "  [--frames N] [--stats STATS.json] [--graph-dot GRAPH.dot]\n"
    "  [--key-light spot|point|directional] [--ground]  (add a light placed from the bounds, printed;\n"
    "                                    a ground under the model to receive its shadow)\n"
    "  [--key-light-angles AZIMUTH,ELEVATION]  (degrees from the framing view: azimuth toward its\n"
    "                                    right, elevation above the horizon; default: to the side, so\n"
    "                                    the shadow falls where the framing camera sees it)\n"
    "  [--orbit-light NAME] [--orbit-camera]\n"
    "  [--time T]  (pose every animation of the scene at T seconds; default: the rest pose)\n"
    "  [--animate NAME|all [--fps F]]  (play that animation, or all: frame i at T + i/F, F default 30)\n"
    "  [--truth]   (per light: map time, acne/leak against ray-traced shadows, and a map texel's\n"
    "              size on screen in pixels, mean/p95)\n"
    "  [--texel-density NAME=HEAT.png]...  (a heat map of that light's map texel size on screen, m\n"
    "               (LogPSM): green one texel per pixel, blue finer, yellow then red coarser, on a\n"
    "               log scale (printed, docs/metrics.md); grey where m has no value: background,\n"
    "               outside the light's evaluation set, no map layer, edge-on to the light)\n"
    "  [--truth-mask NAME=TRUTH.png]...  (implies --truth: the truth that light is scored against, as\n"
    "               --shadow-mask writes its shade: 255 lit, 0 shadowed; for a light with a size the\n"
    "               share of it each pixel sees; pixels outside the evaluation set 0, as the mask's\n"
    "               background)\n"
    "  [--warmup N] (untimed frames first: at least N, default 1, then until a frame compiles no\n"
    "               new shader (up to 4 more), so no timed frame pays for compilation; 0: none)\n"
    "  [--set PLUGIN.KEY=JSON]...  (a plugin's config setting, e.g. shadowmap_plugin.cache_maps=false)\n"
    "  [--exposure EV100|auto]  (for lights in physical units, candela and lux: a sunlit scene 15, an\n"
    "                       office 8; replaces the config's renderer.exposure with 1 / (1.2 * 2^EV100);\n"
    "                       auto: the EV100 that maps the first frame's log-average luminance to middle\n"
    "                       grey 0.18, measured from probe renders of it, printed, kept for every frame)\n"
    "  [--msaa 1|2|4|8]  (samples per pixel of the image, antialiasing its edges: replaces the config's\n"
    "                       renderer.msaa; masks and --truth stay per pixel)\n"
    "  a light's setting: defaults < config and --set < the light's glTF extras < --light-set\n"
    "  without --config: the installed or build tree's engine.json; --version: the version\n";

namespace {

// Bounds of typos, not of the GL: the renderer checks what it can allocate.
constexpr int kMaxSize = 16384, kMaxFrames = 100000, kMaxWarmup = 1000;
constexpr double kMinFps = 1e-3, kMaxFps = 1e4;

// One of the sample counts renderer.msaa accepts.
int parseMsaa(const std::string& flag, const std::string& value) {
    const int samples =
        tools::parseInteger(flag, value, engine::kMsaaSampleCounts.front(), engine::kMsaaSampleCounts.back());
    if (!engine::isMsaaSampleCount(samples))
        throw std::invalid_argument(flag + " " + value + ": must be " + engine::msaaSampleCountsText());
    return samples;
}

// Every image engine-render writes is PNG (lossless: masks and maps are measured): a file
// named otherwise would hold PNG bytes under a name that says something else.
std::string pngPath(const std::string& flag, const std::string& path) {
    const auto dot = path.rfind('.');
    std::string extension = dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot);
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png")
        throw std::invalid_argument(flag + " " + path + ": engine-render writes PNG only; name the file *.png");
    return path;
}

std::pair<std::string, std::string> parsePngAssignment(const std::string& flag, const std::string& text) {
    auto assignment = tools::parseAssignment(flag, text);
    pngPath(flag, assignment.second);
    return assignment;
}

} // namespace

RenderOptions parseRenderOptions(int argc, char** argv) {
    RenderOptions options;
    bool sawScene = false, sawOut = false;
    options.help = tools::parseFlags(argc, argv, {"--orbit-camera", "--truth", "--list", tools::kGroundFlag},
                                     [&](const std::string& flag, const std::string& value) {
        if (flag == "--orbit-camera") options.orbitCamera = true;
        else if (flag == "--truth") options.truth = true;
        else if (flag == "--list") options.list = true;
        else if (flag == "--config") options.config = value;
        else if (flag == "--scene") { options.scene = value; sawScene = true; }
        else if (flag == "--out") { options.out = pngPath(flag, value); sawOut = true; }
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--camera") options.camera = value;
        else if (flag == "--light") options.lightSettings.push_back(tools::parseLightVariant(flag, value));
        else if (flag == "--light-set") options.lightSettings.push_back(tools::parseLightSetting(flag, value));
        else if (flag == "--shadow-mask") options.shadowMasks.push_back(parsePngAssignment(flag, value));
        else if (flag == "--shadow-map") options.shadowMaps.push_back(parsePngAssignment(flag, value));
        else if (flag == "--shadow-compare") options.comparisons.push_back(parsePngAssignment(flag, value));
        else if (flag == "--truth-mask") options.truthMasks.push_back(parsePngAssignment(flag, value));
        else if (flag == "--texel-density") options.texelDensities.push_back(parsePngAssignment(flag, value));
        else if (flag == "--light-tiles") options.lightTiles = pngPath(flag, value);
        else if (flag == "--frames") options.frames = tools::parseInteger(flag, value, 1, kMaxFrames);
        else if (flag == "--warmup") options.warmup = tools::parseInteger(flag, value, 0, kMaxWarmup);
        else if (flag == "--set") tools::addSettingOverride(options.pluginSettings, flag, value);
        else if (flag == "--exposure" && value == tools::kAutoExposureWord) options.autoExposure = true;
        else if (flag == "--exposure") options.exposureEv100 = tools::parseNumber(flag, value, tools::kMinEv100, tools::kMaxEv100);
        else if (flag == "--msaa") options.msaa = parseMsaa(flag, value);
        else if (flag == "--stats") options.stats = value;
        else if (flag == "--graph-dot") options.graphDot = value;
        else if (tools::parseSceneLightingFlag(options.lighting, flag, value)) {}
        else if (flag == "--orbit-light") options.orbitLight = value;
        else if (flag == "--time") options.time = tools::parseNumber(flag, value, 0.0, tools::kMaxAnimationSeconds);
        else if (flag == "--animate") options.animate = value;
        else if (flag == "--fps") options.fps = tools::parseNumber(flag, value, kMinFps, kMaxFps);
        else return false;
        return true;
    });
    if (options.help) return options;
    if (!sawScene) throw std::invalid_argument("--scene is required");
    if (!sawOut && !options.list) throw std::invalid_argument("--out is required");
    if (options.fps && options.animate.empty()) throw std::invalid_argument("--fps needs --animate");
    if (options.autoExposure && options.exposureEv100)
        throw std::invalid_argument("--exposure: given both as auto and as an EV100; give one");
    // The truth a mask shows is the one the scoring computes: one evaluation gives both, and the
    // printed errors are then those of the image written.
    if (!options.truthMasks.empty()) options.truth = true;
    // Two outputs in one file: the later would silently replace the earlier.
    const std::vector<std::string> files = outputFiles(options);
    for (std::size_t i = 0; i < files.size(); ++i)
        for (std::size_t j = i + 1; j < files.size(); ++j)
            if (std::filesystem::path(files[i]).lexically_normal() == std::filesystem::path(files[j]).lexically_normal())
                throw std::invalid_argument(files[j] + ": named for two outputs; give each its own file");
    // --list reads only the scene: it needs no config, found or not.
    if (options.config.empty() && !options.list) options.config = tools::defaultConfigPath();
    return options;
}

std::vector<std::string> outputFiles(const RenderOptions& options) {
    std::vector<std::string> files;
    if (!options.out.empty()) files.push_back(options.out);
    for (const auto* perLight : {&options.shadowMasks, &options.truthMasks, &options.shadowMaps, &options.comparisons,
                                &options.texelDensities})
        for (const auto& [light, file] : *perLight) files.push_back(file);
    for (const std::string* file : {&options.stats, &options.graphDot})
        if (!file->empty()) files.push_back(*file);
    return files;
}
