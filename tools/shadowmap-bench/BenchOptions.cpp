#include "BenchOptions.h"

#include "SceneLighting.h"

#include "CommandLine.h"
#include "AnimationPlayback.h"
#include "OptionValues.h"

#include "engine/util/FormatNumber.h"
#include "engine/util/InstallLayout.h"
#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace shadowmap_bench {

namespace {

// The default sweep (2 scenes, 4 lights, 54 settings): 4 minutes on 2 cores (AMD EPYC,
// llvmpipe) while other jobs kept the load near 7, well inside a coffee break. The four
// masked/opaque scenes at 9 settings each add about 2 minutes (3.5 s per setting and scene
// at 1280x720, load near 6; the full grid would add 12).
constexpr const char* kEngineModel =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
constexpr int kDefaultWidth = 1280, kDefaultHeight = 720, kDefaultFrames = 5;

// What the sweep may set, as the shadow plugin accepts it (shadowmap::settingKeys()): every
// depth format and filter, every variant but "none" (no map: nothing to time or measure).
std::vector<std::string> knownVariants() {
    std::vector<std::string> variants = shadowmap::settingKey("variant").choices;
    std::erase(variants, shadowmap::toString(shadowmap::Variant::None));
    return variants;
}
std::vector<std::string> knownFormats() { return shadowmap::settingKey("depth_format").choices; }
std::vector<std::string> knownFilters() { return shadowmap::settingKey("filter").choices; }

// The source tree's content/ for a tool of the build tree, else the install's
// share/shadow-engine, which holds the same engine.json and scenes/ (InstallLayout.h: an
// installed bench never reads a source tree that happens to sit where its builder had one).
std::string contentDir() { return engine::buildTreeDataDir().value_or(engine::installedDataDir()).string(); }

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
    return text;
}

// The toolkit's light types, or none: a scene without a light is then an error.
std::optional<engine::Light::Type> parseKeyLight(const std::string& flag, const std::string& text) {
    if (text == "none") return std::nullopt;
    try {
        return tools::parseLightType(flag, text);
    } catch (const std::invalid_argument&) {
        throw std::invalid_argument(flag + ": \"" + text + "\" is not spot, point, directional or none");
    }
}

// The optional axes' lists, each value bounded as the shadow plugin bounds its key (the
// bounds are stated there once); a key without a bound takes any finite number that way.
std::vector<double> parseSettingNumbers(const std::string& flag, const std::string& text, std::string_view key) {
    constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    const shadowmap::SettingKey& bounds = shadowmap::settingKey(key);
    return tools::parseNumberList(flag, text, bounds.minimum.value_or(-kUnbounded), bounds.maximum.value_or(kUnbounded));
}
std::vector<int> parseSettingIntegers(const std::string& flag, const std::string& text, std::string_view key) {
    const shadowmap::SettingKey& bounds = shadowmap::settingKey(key);
    return tools::parseIntegerList(flag, text, static_cast<int>(*bounds.minimum), static_cast<int>(*bounds.maximum));
}

// --projections: the plugin's projections (settingKey("projection")).
std::vector<std::string> knownProjections() { return shadowmap::settingKey("projection").choices; }
std::vector<shadowmap::Projection> parseProjections(const std::string& flag, const std::string& text) {
    std::vector<shadowmap::Projection> projections;
    for (const std::string& item : tools::parseNames(flag, text, knownProjections()))
        for (shadowmap::Projection projection : {shadowmap::Projection::Uniform, shadowmap::Projection::Lispsm})
            if (item == shadowmap::toString(projection)) projections.push_back(projection);
    return projections;
}

// --cascades: "auto" and each count the plugin accepts, in the key's order: auto,1,2,3,4.
std::vector<std::string> knownCascades() {
    const shadowmap::SettingKey& key = shadowmap::settingKey("cascades");
    std::vector<std::string> known = key.choices;
    for (int count = static_cast<int>(*key.minimum); count <= static_cast<int>(*key.maximum); ++count)
        known.push_back(std::to_string(count));
    return known;
}
std::vector<int> parseCascades(const std::string& flag, const std::string& text) {
    std::vector<int> counts;
    for (const std::string& item : tools::parseNames(flag, text, knownCascades()))
        counts.push_back(item == "auto" ? shadowmap::kAutoCascades : std::stoi(item));
    return counts;
}

std::vector<bool> parseStables(const std::string& flag, const std::string& text) {
    std::vector<bool> stables;
    for (const std::string& item : tools::parseNames(flag, text, {"true", "false"})) stables.push_back(item == "true");
    return stables;
}

// "0..16" as the plugin bounds the key.
std::string bounds(std::string_view key) {
    const shadowmap::SettingKey& setting = shadowmap::settingKey(key);
    return engine::formatNumber(*setting.minimum) + ".." + engine::formatNumber(*setting.maximum);
}

bool lists(const std::vector<std::string>& filters, shadowmap::Filter filter) {
    return std::find(filters.begin(), filters.end(), shadowmap::toString(filter)) != filters.end();
}

// Whether --filters lists a filter that reads depth moments (vsm, evsm).
bool listsMoments(const std::vector<std::string>& filters) {
    return lists(filters, shadowmap::Filter::Vsm) || lists(filters, shadowmap::Filter::Evsm);
}

// Axes that would multiply no row are refused rather than ignored: the sweep would not
// measure what the command line asked for.
void checkAxes(const BenchOptions& options) {
    if (!options.lightRadii.empty() && !options.angularDiameters.empty() &&
        options.lightRadii.size() != options.angularDiameters.size())
        throw std::invalid_argument("--light-radii and --angular-diameters: " + std::to_string(options.lightRadii.size()) +
                                    " and " + std::to_string(options.angularDiameters.size()) +
                                    " values; the k-th of each make the k-th light size step, so list as many of each");
    const bool pcf = lists(options.filters, shadowmap::Filter::Pcf);
    const bool moments = listsMoments(options.filters);
    if (!options.filterRadii.empty() && !pcf && !moments)
        throw std::invalid_argument("--filter-radii: only pcf, vsm and evsm have a filter radius, and --filters lists "
                                    "none of them");
    const bool widePcf = pcf && std::any_of(options.filterRadii.begin(), options.filterRadii.end(),
                                            [](double radius) { return radius > 0.0; });
    if (!options.filterTaps.empty() && !widePcf && !lists(options.filters, shadowmap::Filter::Pcss))
        throw std::invalid_argument("--filter-taps: only pcss and pcf with a --filter-radii value above 0 take taps, "
                                    "and the sweep has neither");
    if (!options.bleedReductions.empty() && !moments)
        throw std::invalid_argument("--bleed-reductions: only vsm and evsm have a bleed reduction, and --filters lists "
                                    "neither");
    if (!options.stables.empty() && !options.projections.empty() &&
        std::all_of(options.projections.begin(), options.projections.end(),
                    [](shadowmap::Projection projection) { return projection == shadowmap::Projection::Lispsm; }))
        throw std::invalid_argument("--stables: a lispsm warp is never stable (the plugin ignores stable there), "
                                    "and --projections lists only lispsm");
}

} // namespace

const char* benchUsage() {
    // The lists and the masked scenes' format and filter are the plugin's (settingKeys()).
    const shadowmap::ShadowSettings defaults;
    static const std::string usage =
        "usage: shadowmap-bench --out DIR [--config CONFIG.json] [--scene SCENE.gltf|.glb]...\n"
        "  [--camera NAME] [--width W --height H] [--frames N]\n"
        "  [--variants " + joined(knownVariants()) + "] [--resolutions 512,1024,2048,4096]\n"
        "  [--depth-formats " + joined(knownFormats()) + "] [--filters " + joined(knownFilters()) + "]\n"
        "  [--key-light spot|point|directional|none] [--ground]   (--ground: a ground under each scene\n"
        "                       that receives shadows and casts none)\n"
        "  [--shimmer N]        also measure shimmer: N frames of the camera panning one pixel a\n"
        "                       frame (evaluation/CameraPath.h); results.csv's shimmer column\n"
        "                       (percent of surface points whose shadow state changed between frames\n"
        "                       while the truth did not; docs/metrics.md)\n"
        "  [--near D]           also score each light on the pixels within D of the camera (world\n"
        "                       units): results.csv's near_error, near_error_noedge\n"
        "  [--time T,...]       measure each scene posed at each listed time in seconds (every\n"
        "                       animation of the file, skins and morph targets included; the truth\n"
        "                       traces the same pose); the scene column reads <name>@<T>s\n"
        "  [--shard K/N]        run every N-th job only (jobs: scene x setting, numbered in sweep\n"
        "                       order; shard K runs K-1, K-1+N, ...) and write DIR/shard.json beside\n"
        "                       the results\n"
        "  [--merge SHARD_DIR]... with --out DIR: merge shards 1..N of one sweep into DIR (results.csv\n"
        "                       in the single run's order, summary.md, plot); renders nothing\n"
        "Optional axes (each multiplies the rows it applies to; not given: the key is not written,\n"
        "the light keeps its scene's or the engine config's value, and the column is empty):\n"
        "  [--light-radii R,...] [--angular-diameters A,...]   light size steps: the k-th step gives\n"
        "                       spot and point lights light_radius R[k] (world units), directional\n"
        "                       lights angular_diameter A[k] (radians); both given: equal lengths;\n"
        "                       one given: the other type of light keeps its own size\n"
        "  [--filter-radii F,...] pcf, vsm and evsm rows: filter_radius " + bounds("filter_radius") +
        " texels (pcf: the disk's\n"
        "                       radius; vsm, evsm: the moments' box blur, texels each side)\n"
        "  [--filter-taps T,...] pcss rows and pcf rows with a filter radius > 0: filter_taps " +
        bounds("filter_taps") + "\n"
        "  [--bleed-reductions B,...] vsm and evsm rows only: bleed_reduction " + bounds("bleed_reduction") + "\n"
        "  [--normal-offsets N,...] every row: normal_offset " + bounds("normal_offset") + " texels\n"
        "  Directional lights only (each setting still applies to all of a scene's lights: a spot or\n"
        "  point light keeps its own value, and its row is written once, for the first value listed,\n"
        "  not once per value):\n"
        "  [--projections " + joined(knownProjections()) + "] every row: projection\n"
        "  [--cascades " + joined(knownCascades()) + "] every row: cascades (auto: the count the view needs)\n"
        "  [--stables true,false] rows whose projection is not lispsm: stable (cascades snapped to\n"
        "                       whole texels); a lispsm warp follows the camera and is never stable,\n"
        "                       so lispsm rows keep the scene's value, which the plugin ignores there;\n"
        "                       one map (cascades 1 without a shadow_distance) is fitted either way,\n"
        "                       so its stable and unstable rows agree but for timing noise\n"
        "  A step a scene's lights refuse (pcss at a size of 0, pcss, vsm or evsm with lispsm, vsm or\n"
        "  evsm on a spot or point light with an infinite far plane) is left out with one note.\n"
        "  Labels (progress, summary, plot) add what is set: lr<R> ad<A> (a size step; per light in\n"
        "  the summary and plot: size<S>, the size it had), fr<F>, taps<T>, br<B>, no<N>,\n"
        "  uniform|lispsm, c<1..4|auto>, stable|unstable, e.g.\n"
        "  \"standard 1024 d24 pcss lr0.1 ad0.05 taps32 no0.25\", \"standard 1024 d24 vsm fr2 br0.2\",\n"
        "  \"woo 2048 d24 pcf lispsm c2\", \"standard 2048 d24 pcf uniform cauto unstable\".\n"
        "\n"
        "Renders every scene with every combination of the listed settings applied to all of its\n"
        "lights, times each light's shadow passes (median wall time over N frames, each pass closed\n"
        "by glFinish) and measures its error against ray-traced shadows (Embree). Writes\n"
        "  DIR/results.csv      scene,light,variant,resolution,depth_format,filter,shadow_ms,\n"
        "                       frame_ms,acne,leak,error,error_noedge,area_acne,area_leak,area_error,\n"
        "                       shimmer,near_error,near_error_noedge,light_size,filter_radius,\n"
        "                       filter_taps,normal_offset,soft_error,soft_error_noedge,penumbra_error,\n"
        "                       texel_m_mean,texel_m_p95,projection,cascades,stable,bleed_reduction,\n"
        "                       frame_p99_ms,frame_max_ms\n"
        "                       (errors in percent; resolution, depth_format, filter: empty on a\n"
        "                       volume row, which has no map: one per light and size step, taking\n"
        "                       none of the other axes; light_size: the radius or angular diameter the\n"
        "                       light had, 0: none; filter_radius, filter_taps, normal_offset,\n"
        "                       projection, cascades, stable, bleed_reduction: empty where not swept\n"
        "                       or not applying (projection, cascades, stable: always on spot and\n"
        "                       point lights' rows; bleed_reduction: on rows other than vsm, evsm);\n"
        "                       soft_*, penumbra_error: against the soft truth, the visible fraction\n"
        "                       of the light, for a light with a size only;\n"
        "                       texel_m_*: a map texel's size on screen in pixels, mean and 95th\n"
        "                       percentile over the evaluated pixels; frame_ms: the median frame,\n"
        "                       frame_p99_ms, frame_max_ms: p99 and max of the same frames)\n"
        "  DIR/summary.md       per light: the most accurate setting within 2, 5, 10, 20, 50 ms of\n"
        "                       shadow time, and the Pareto front of time against error (error: the\n"
        "                       soft error for a light with a size, else the area error)\n"
        "  DIR/time_vs_error.gp and .png  (one panel per scene; the png needs gnuplot)\n"
        "\n"
        "Defaults (the default sweep: 540 map rows and one volume row per light; its 324 rows before vsm\n"
        "and evsm took about 6 minutes on 2 cores):\n"
        "  --config   <source>/content/engine.json (installed: <prefix>/share/shadow-engine/engine.json)\n"
        "  --scene    <source>/content/scenes/showcase.gltf and, when assimp-testmodels is\n"
        "             installed, /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb;\n"
        "             and the alpha-masked scenes with their opaque twins, masked_fence, opaque_fence,\n"
        "             masked_canopy, opaque_canopy (.gltf), over the variants and resolutions at\n"
        "             " + shadowmap::toString(defaults.depthFormat) + " and " + shadowmap::toString(defaults.filter) +
        " only (else the first depth format and filter listed), times the optional axes\n"
        "  --camera   the scene's first camera, else one framing the scene\n"
        "  --width 1280 --height 720 --frames 5\n"
        "  --variants " + joined(knownVariants()) + " --resolutions 512,1024,2048\n"
        "  --depth-formats " + joined(knownFormats()) + " --filters " + joined(knownFilters()) + "\n"
        "  --key-light spot   (added to scenes that have no light; none: such a scene is an error)\n";
    return usage.c_str();
}

BenchOptions parseBenchOptions(int argc, char** argv) {
    BenchOptions options;
    options.config = contentDir() + "/engine.json";
    options.width = kDefaultWidth;
    options.height = kDefaultHeight;
    options.frames = kDefaultFrames;
    options.variants = knownVariants();
    options.resolutions = {512, 1024, 2048};
    options.depthFormats = knownFormats();
    options.filters = knownFilters();

    // The plugin's own bounds; it checks the GL's GL_MAX_TEXTURE_SIZE when it renders.
    const shadowmap::SettingKey& resolution = shadowmap::settingKey("resolution");
    const int minResolution = static_cast<int>(*resolution.minimum), maxResolution = static_cast<int>(*resolution.maximum);
    options.help = tools::parseFlags(argc, argv, {tools::kGroundFlag}, [&](const std::string& flag, const std::string& value) {
        if (flag == "--config") options.config = value;
        else if (flag == "--scene") {
            options.defaultScenes = false;
            options.scenes.push_back(value);
        } else if (flag == "--camera") options.camera = value;
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, 16384);
        else if (flag == "--frames") options.frames = tools::parseInteger(flag, value, 1, 10000);
        else if (flag == "--shimmer") options.shimmerFrames = tools::parseInteger(flag, value, 2, 10000);
        else if (flag == "--near") options.nearDistance = tools::parsePositiveNumber(flag, value, 1e12);
        else if (flag == "--variants") options.variants = tools::parseNames(flag, value, knownVariants());
        else if (flag == "--resolutions") options.resolutions = tools::parseIntegerList(flag, value, minResolution, maxResolution);
        else if (flag == "--depth-formats") options.depthFormats = tools::parseNames(flag, value, knownFormats());
        else if (flag == "--filters") options.filters = tools::parseNames(flag, value, knownFilters());
        else if (flag == "--light-radii") options.lightRadii = parseSettingNumbers(flag, value, "light_radius");
        else if (flag == "--angular-diameters") options.angularDiameters = parseSettingNumbers(flag, value, "angular_diameter");
        else if (flag == "--filter-radii") options.filterRadii = parseSettingNumbers(flag, value, "filter_radius");
        else if (flag == "--filter-taps") options.filterTaps = parseSettingIntegers(flag, value, "filter_taps");
        else if (flag == "--bleed-reductions") options.bleedReductions = parseSettingNumbers(flag, value, "bleed_reduction");
        else if (flag == "--normal-offsets") options.normalOffsets = parseSettingNumbers(flag, value, "normal_offset");
        else if (flag == "--projections") options.projections = parseProjections(flag, value);
        else if (flag == "--cascades") options.cascades = parseCascades(flag, value);
        else if (flag == "--stables") options.stables = parseStables(flag, value);
        else if (flag == "--key-light") options.keyLight = parseKeyLight(flag, value);
        else if (flag == "--time") options.times = tools::parseNumberList(flag, value, 0.0, tools::kMaxAnimationSeconds);
        else if (flag == tools::kGroundFlag) options.ground = true;
        else if (flag == "--out") options.out = value;
        else if (flag == "--shard") {
            const tools::Shard shard = tools::parseShard(flag, value);
            options.shardIndex = shard.index;
            options.shardCount = shard.count;
        } else if (flag == "--merge") options.merge.push_back(value);
        else return false;
        return true;
    });
    if (options.help) return options;
    if (options.out.empty()) throw std::invalid_argument("--out is required");
    if (!options.merge.empty() && options.shardCount > 1)
        throw std::invalid_argument("--merge and --shard exclude each other: merge after every shard ran");
    checkAxes(options);
    if (options.defaultScenes) {
        const std::string scenes = contentDir() + "/scenes/";
        options.scenes = {scenes + "showcase.gltf", kEngineModel};
        for (const char* name : {"masked_fence", "opaque_fence", "masked_canopy", "opaque_canopy"})
            options.maskedScenes.push_back(scenes + name + ".gltf");
    }
    return options;
}

} // namespace shadowmap_bench
