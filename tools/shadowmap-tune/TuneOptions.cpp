#include "TuneOptions.h"

#include "CommandLine.h"
#include "OptionValues.h"

#include "shadowmap/ShadowSettings.h"

#include <stdexcept>

namespace shadowmap_tune {

namespace {

// Measured at the size the user will look at (tools::kDefaultImageWidth/Height, engine-render's
// default): a setting's error depends on the image size. At 320x240 the showcase's three
// lights chose 512² d16 maps whose error at 1280x720 was 1.6 to 2.4 times the file's own.
constexpr int kDefaultFrames = 3;
constexpr int kDefaultOrbitViews = 4;
// pcss candidates' taps: the plugin's default 16 with half and twice as many (the coarse pass
// tries the fewest, the fine pass the others; more than 32 costs a lot on a CPU renderer
// for a penumbra smoothed over a few pixels).
const std::vector<int> kDefaultPcssTaps = {8, 16, 32};

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
    return text;
}

std::vector<std::string> knownVariants() {
    std::vector<std::string> variants = shadowmap::settingKey("variant").choices;
    std::erase(variants, shadowmap::toString(shadowmap::Variant::None));
    return variants;
}

} // namespace

ViewSpec parseViewSpec(const std::string& flag, const std::string& text) {
    ViewSpec spec;
    spec.given = true;
    if (text == "cameras") return spec;
    if (text.rfind("orbit:", 0) == 0) {
        spec.kind = ViewSpec::Kind::Orbit;
        spec.count = tools::parseInteger(flag, text.substr(6), 1, 64);
        return spec;
    }
    throw std::invalid_argument(flag + ": unknown view spec \"" + text + "\" (cameras or orbit:N)");
}

const char* tuneUsage() {
    static const std::string filters = joined(shadowmap::settingKey("filter").choices);
    static const std::string defaultSize =
        std::to_string(tools::kDefaultImageWidth) + " --height " + std::to_string(tools::kDefaultImageHeight);
    static const std::string usage =
        "usage: shadowmap-tune --scene SCENE.gltf|.glb (--budget-ms B | --max-error E) --out TUNED.gltf|.glb\n"
        "  [--views cameras|orbit:N] [--config CONFIG.json] [--frames N]\n"
        "  [--width W --height H]   the image size you will render and look at: every setting is\n"
        "                  measured at it (a coarse map scores well on a small image and shows its\n"
        "                  texels on a large one); recorded in --out's asset.extras.shadowmap_tune\n"
        "  [--variants standard,woo,backface,volume] [--resolutions 512,1024,2048]\n"
        "  [--depth-formats d16,d24,d32f] [--filters " + filters + "] [--filter-taps 8,16,32]\n"
        "  [--report REPORT.json]\n"
        "  [--key-light spot|point|directional] [--key-light-angles AZIMUTH,ELEVATION]   a scene\n"
        "                  without lights gets this key light (placed from its bounds as\n"
        "                  engine-render places it), tuned and written into --out\n"
        "  [--ground]      a ground under the model receives the shadows while measuring, as\n"
        "                  engine-render --ground shows them (not written into --out)\n"
        "  [--shard K/N]   search every N-th light only and write --out as a partial result (JSON)\n"
        "usage: shadowmap-tune --scene SCENE --merge PART.json... --out TUNED.gltf|.glb\n"
        "                  write the scene from shards 1..N's partial results (renders nothing)\n"
        "\n"
        "Chooses each light's shadow setting by measurement: the most accurate within B ms of\n"
        "shadow passes per frame (--budget-ms), or the cheapest whose error is at most E percent\n"
        "(--max-error), over variant x resolution x depth format x filter (x filter taps for pcss,\n"
        "which only a light with a size takes), with the polygon and normal offsets fitted per\n"
        "light; volume (stenciled shadow volumes: no map, exact hard shadows) is one candidate,\n"
        "without resolution, format, filter or offsets, whose cost grows with the image size.\n"
        "vsm and evsm keep the light's own filter_radius (their blur) and bleed_reduction;\n"
        "a setting the light refuses (pcss without a size, vsm or evsm with lispsm or a spot or\n"
        "point light's infinite far plane, backface with open casters) is never tried. Error is\n"
        "acne + leak against ray-traced truth: the soft truth (the visible share of the light)\n"
        "for a light with a size, else the area truth; pooled over the views:\n"
        "every glTF camera, or N views around the scene. Writes the scene with each changed\n"
        "light's extras.shadow (every other byte kept when --out has the scene's container; the\n"
        "scene's buffers and images go with it to any folder or into a .glb) and prints\n"
        "per light: old -> new setting, time and error (soft or area) before and after, the fitted\n"
        "offsets beside the defaults, and how many renders the search took against the full grid.\n"
        "\n"
        "Defaults: --views cameras (orbit:4 for a scene without cameras) --width " + defaultSize + "\n"
        "  (engine-render's default size) --frames 3, every variant but none, resolutions\n"
        "  512,1024,2048, every format and filter, filter taps 8,16,32.\n";
    return usage.c_str();
}

TuneOptions parseTuneOptions(int argc, char** argv) {
    TuneOptions options;
    options.width = tools::kDefaultImageWidth;
    options.height = tools::kDefaultImageHeight;
    options.frames = kDefaultFrames;
    options.views.count = kDefaultOrbitViews;
    options.limits = {knownVariants(), shadowmap::settingKey("depth_format").choices,
                      shadowmap::settingKey("filter").choices, {512, 1024, 2048}, kDefaultPcssTaps};
    bool maxError = false;
    const shadowmap::SettingKey& resolution = shadowmap::settingKey("resolution");
    const shadowmap::SettingKey& taps = shadowmap::settingKey("filter_taps");
    options.help = tools::parseFlags(argc, argv, {tools::kGroundFlag}, [&](const std::string& flag, const std::string& value) {
        if (flag == "--config") options.config = value;
        else if (flag == "--scene") options.scene = value;
        else if (flag == "--out") options.out = value;
        else if (flag == "--report") options.report = value;
        else if (flag == "--budget-ms") {
            options.budget = true;
            options.limit = tools::parsePositiveNumber(flag, value, 1e6);
        } else if (flag == "--max-error") {
            maxError = true;
            options.limit = tools::parsePositiveNumber(flag, value, 100.0);
        } else if (flag == "--shard") options.shard = tools::parseShard(flag, value);
        else if (flag == "--merge") options.merge.push_back(value);
        else if (flag == "--views") options.views = parseViewSpec(flag, value);
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--frames") options.frames = tools::parseInteger(flag, value, 1, 10000);
        else if (flag == "--variants") options.limits.variants = tools::parseNames(flag, value, knownVariants());
        else if (flag == "--resolutions")
            options.limits.resolutions = tools::parseIntegerList(flag, value, static_cast<int>(*resolution.minimum),
                                                                 static_cast<int>(*resolution.maximum));
        else if (flag == "--depth-formats")
            options.limits.depthFormats = tools::parseNames(flag, value, shadowmap::settingKey("depth_format").choices);
        else if (flag == "--filters")
            options.limits.filters = tools::parseNames(flag, value, shadowmap::settingKey("filter").choices);
        else if (flag == "--filter-taps")
            options.limits.filterTaps = tools::parseIntegerList(flag, value, static_cast<int>(*taps.minimum),
                                                                static_cast<int>(*taps.maximum));
        else if (tools::parseSceneLightingFlag(options.lighting, flag, value)) {}
        else return false;
        return true;
    });
    if (options.help) return options;
    if (options.scene.empty()) throw std::invalid_argument("--scene is required");
    if (options.out.empty()) throw std::invalid_argument("--out is required");
    if (options.lighting.keyLight && (options.shard.count > 1 || !options.merge.empty()))
        throw std::invalid_argument(std::string("--key-light and ") + (options.merge.empty() ? "--shard" : "--merge") +
                                    " exclude each other: the key light is the scene's only light, nothing to split");
    if (!options.merge.empty()) {
        if (options.shard.count > 1) throw std::invalid_argument("--merge and --shard exclude each other");
        return options;  // the goal and the views were the shards'
    }
    if (options.budget == maxError)
        throw std::invalid_argument(options.budget ? "--budget-ms and --max-error exclude each other: give one"
                                                   : "give --budget-ms B or --max-error E");
    if (options.config.empty()) options.config = tools::defaultConfigPath();
    return options;
}

} // namespace shadowmap_tune
