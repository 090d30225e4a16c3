#include "RenderOptions.h"

#include "CommandLine.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>

const char* const kRenderUsage =
    "usage: engine-render --config CONFIG.json --scene SCENE.gltf|.glb --out OUT.png\n"
    "       engine-render --scene SCENE.gltf|.glb --list   (its cameras and lights, numbered)\n"
    "  [--width W] [--height H] [--camera NAME|NUMBER]\n"
    "  (a light or camera is named by its name, its node's name, or its number in --list)\n"
    "  [--light NAME=VARIANT]... [--shadow-mask NAME=MASK.png]... [--shadow-map NAME=MAP.png]...\n"
    "  [--shadow-compare NAME=VIEW.png]...  (green: r agrees with the map, red: shadowed)\n"
    "  [--frames N] [--stats STATS.json] [--graph-dot GRAPH.dot]\n"
    "  [--key-light spot|point|directional] [--orbit-light NAME] [--orbit-camera]\n"
    "  [--truth]   (per light: map time, and acne/leak against ray-traced shadows)\n"
    "  [--warmup N] (untimed frames first, default 1) [--set PLUGIN.KEY=JSON]...\n";

namespace {

int parsePositive(const std::string& flag, const std::string& text, int maximum) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < 1 || value > maximum)
        throw std::invalid_argument(flag + ": \"" + text + "\" is not an integer in [1, " +
                                    std::to_string(maximum) + "]");
    return static_cast<int>(value);
}

std::pair<std::string, std::string> parseAssignment(const std::string& flag,
                                                    const std::string& text) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        throw std::invalid_argument(flag + ": \"" + text + "\" must be NAME=VALUE");
    return {text.substr(0, equals), text.substr(equals + 1)};
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
    auto assignment = parseAssignment(flag, text);
    pngPath(flag, assignment.second);
    return assignment;
}

} // namespace

RenderOptions parseRenderOptions(int argc, char** argv) {
    RenderOptions options;
    bool sawScene = false, sawOut = false;
    options.help = tools::parseFlags(argc, argv, {"--orbit-camera", "--truth", "--list"},
                                     [&](const std::string& flag, const std::string& value) {
        if (flag == "--orbit-camera") options.orbitCamera = true;
        else if (flag == "--truth") options.truth = true;
        else if (flag == "--list") options.list = true;
        else if (flag == "--config") options.config = value;
        else if (flag == "--scene") { options.scene = value; sawScene = true; }
        else if (flag == "--out") { options.out = pngPath(flag, value); sawOut = true; }
        else if (flag == "--width") options.width = parsePositive(flag, value, 16384);
        else if (flag == "--height") options.height = parsePositive(flag, value, 16384);
        else if (flag == "--camera") options.camera = value;
        else if (flag == "--light") options.lightVariants.push_back(parseAssignment(flag, value));
        else if (flag == "--shadow-mask") options.shadowMasks.push_back(parsePngAssignment(flag, value));
        else if (flag == "--shadow-map") options.shadowMaps.push_back(parsePngAssignment(flag, value));
        else if (flag == "--shadow-compare") options.comparisons.push_back(parsePngAssignment(flag, value));
        else if (flag == "--frames") options.frames = parsePositive(flag, value, 100000);
        else if (flag == "--warmup") options.warmup = value == "0" ? 0 : parsePositive(flag, value, 1000);
        else if (flag == "--set") options.pluginSettings.push_back(parseAssignment(flag, value));
        else if (flag == "--stats") options.stats = value;
        else if (flag == "--graph-dot") options.graphDot = value;
        else if (flag == "--key-light") {
            if (value != "spot" && value != "point" && value != "directional")
                throw std::invalid_argument("--key-light: \"" + value + "\" is not spot, point or directional");
            options.keyLight = value;
        } else if (flag == "--orbit-light") options.orbitLight = value;
        else return false;
        return true;
    });
    if (options.help) return options;
    if (!sawScene) throw std::invalid_argument("--scene is required");
    if (!sawOut && !options.list) throw std::invalid_argument("--out is required");
    return options;
}
