#include "ViewOptions.h"

#include "AutoExposure.h"
#include "CommandLine.h"
#include "OptionValues.h"

#include <stdexcept>

namespace engine_view {

const char* const kViewUsage =
    "usage: engine-view [--config CONFIG.json] --scene SCENE.gltf|.glb\n"
    "  [--camera NAME|NUMBER] [--width W --height H]   (initial window size, default 1280x720)\n"
    "  [--script FILE]          (one command per frame: key, select, set, view, camera, orbit,\n"
    "                            pan, zoom, frames, screenshot, save, overlay, resize, quit;\n"
    "                            see docs/viewer.md), then quit\n"
    "  [--stay]                 (after the script, stay interactive instead of quitting)\n"
    "  [--screenshot OUT.png]   (the window after the first frame (after the script, if any), then quit)\n"
    "  [--save-settings OUT.gltf|.glb]  (where S writes the scene with the lights' settings;\n"
    "                            checked at start: the folder must exist and be writable)\n"
    "  [--light-set NAME.KEY=JSON]...  (a per-light setting, as if set by the script's `set`;\n"
    "                            NAME.intensity=I and NAME.color=[r,g,b] replace the light's own\n"
    "                            for this session: S saves shadow settings only)\n"
    "  [--light NAME=VARIANT]...        (--light-set NAME.variant=VARIANT)\n"
    "  [--key-light spot|point|directional] [--ground]  (add a light placed from the bounds,\n"
    "                            printed; a ground under the model to receive its shadow)\n"
    "  [--key-light-angles AZIMUTH,ELEVATION]  (degrees from the framing view: azimuth toward\n"
    "                            its right, elevation above the horizon; default: to the side)\n"
    "  [--exposure EV100|auto]  (for lights in physical units: the config's renderer.exposure\n"
    "                            replaced with 1 / (1.2 * 2^EV100); auto: the EV100 that maps the\n"
    "                            first frame's log-average luminance to middle grey 0.18, printed,\n"
    "                            kept while the viewer runs)\n"
    "  [--time T]               (the scene posed at T seconds; default: at rest)\n"
    "  [--animate NAME|all]     (play that animation, or all, from T; Space plays all)\n"
    "keys: Tab light, V variant, R resolution, F depth format, P filter, C cascades,\n"
    "      T stable cascades, [ ] offset units, , . dimming,\n"
    "      - = light size (light_radius, or angular_diameter for a directional light;\n"
    "      down to 0 and back up; at 0 a pcss light's filter becomes pcf),\n"
    "      1-9 glTF cameras, 0 framing camera, D debug view, M texel-density view (and back),\n"
    "      O overlay,\n"
    "      S save settings, Space play/pause, Left/Right step 0.1 s, Esc quit;\n"
    "      mouse: left orbit, right/middle pan, wheel zoom\n";

// The largest window or image side the viewer accepts: a typo bound, not a GL limit.
constexpr int kMaxSize = 16384;

ViewOptions parseViewOptions(int argc, char** argv) {
    ViewOptions options;
    bool sawScene = false;
    options.help = tools::parseFlags(argc, argv, {"--stay", tools::kGroundFlag}, [&](const std::string& flag, const std::string& value) {
        if (flag == "--config") options.config = value;
        else if (flag == "--scene") { options.scene = value; sawScene = true; }
        else if (flag == "--camera") options.camera = value;
        else if (flag == "--width") options.width = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--height") options.height = tools::parseInteger(flag, value, 1, kMaxSize);
        else if (flag == "--script") options.script = value;
        else if (flag == "--time") options.time = tools::parseNumber(flag, value, 0.0, 1e6);
        else if (flag == "--animate") options.animate = value;
        else if (flag == "--stay") options.stay = true;
        else if (flag == "--screenshot") options.screenshot = value;
        else if (flag == "--save-settings") options.saveSettings = value;
        else if (flag == "--exposure" && value == tools::kAutoExposureWord) options.autoExposure = true;
        else if (flag == "--exposure") options.exposureEv100 = tools::parseNumber(flag, value, tools::kMinEv100, tools::kMaxEv100);
        else if (flag == "--light") options.lightSettings.push_back(tools::parseLightVariant(flag, value));
        else if (flag == "--light-set") options.lightSettings.push_back(tools::parseLightSetting(flag, value));
        else if (tools::parseSceneLightingFlag(options.lighting, flag, value)) {}
        else return false;
        return true;
    });
    if (options.help) return options;
    if (!sawScene) throw std::invalid_argument("--scene is required");
    if (options.autoExposure && options.exposureEv100)
        throw std::invalid_argument("--exposure: given both as auto and as an EV100; give one");
    if (options.config.empty()) options.config = tools::defaultConfigPath();
    return options;
}

} // namespace engine_view
