#include "ViewOptions.h"

#include "CommandLine.h"

#include <cerrno>
#include <cstdlib>
#include <stdexcept>

const char* const kViewUsage =
    "usage: engine-view --config CONFIG.json --scene SCENE.gltf|.glb\n"
    "  [--camera NAME|NUMBER] [--width W --height H]   (initial window size, default 1280x720)\n"
    "  [--script FILE]          (one command per frame: key, select, set, view, camera, orbit,\n"
    "                            pan, zoom, frames, screenshot, save, overlay, resize, quit;\n"
    "                            see the README), then quit\n"
    "  [--stay]                 (after the script, stay interactive instead of quitting)\n"
    "  [--screenshot OUT.png]   (the window after the first frame (after the script, if any), then quit)\n"
    "  [--save-settings OUT.gltf|.glb]  (where S writes the scene with the lights' settings)\n"
    "keys: Tab light, V variant, R resolution, F depth format, P filter, [ ] offset units,\n"
    "      , . dimming, 1-9 glTF cameras, 0 framing camera, D debug view, O overlay,\n"
    "      S save settings, Esc quit; mouse: left orbit, right/middle pan, wheel zoom\n";

namespace {

int parseSize(const std::string& flag, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < 1 || value > 16384)
        throw std::invalid_argument(flag + ": \"" + text + "\" is not an integer in [1, 16384]");
    return static_cast<int>(value);
}

} // namespace

ViewOptions parseViewOptions(int argc, char** argv) {
    ViewOptions options;
    bool sawScene = false;
    options.help = tools::parseFlags(argc, argv, {"--stay"}, [&](const std::string& flag, const std::string& value) {
        if (flag == "--config") options.config = value;
        else if (flag == "--scene") { options.scene = value; sawScene = true; }
        else if (flag == "--camera") options.camera = value;
        else if (flag == "--width") options.width = parseSize(flag, value);
        else if (flag == "--height") options.height = parseSize(flag, value);
        else if (flag == "--script") options.script = value;
        else if (flag == "--stay") options.stay = true;
        else if (flag == "--screenshot") options.screenshot = value;
        else if (flag == "--save-settings") options.saveSettings = value;
        else return false;
        return true;
    });
    if (options.help) return options;
    if (!sawScene) throw std::invalid_argument("--scene is required");
    return options;
}
