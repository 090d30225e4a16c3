#pragma once
// engine-view's command line.
#include "LightOverrides.h"
#include "OptionValues.h"
#include "SceneLighting.h"

#include <optional>
#include <string>
#include <vector>

namespace engine_view {

struct ViewOptions {
    std::string config;  // empty: tools::defaultConfigPath()
    std::string scene;
    std::string camera;          // empty: first glTF camera, else a framing one
    int width = tools::kDefaultImageWidth, height = tools::kDefaultImageHeight;  // the window's initial size (the image follows resizes)
    std::string script;          // --script FILE: one command per frame (Script.h)
    bool stay = false;           // --stay: after the script, stay interactive (else quit)
    std::string screenshot;      // --screenshot OUT.png: the first frame's window, then quit
    std::string saveSettings;    // --save-settings OUT.gltf|.glb: where S (and `save`) write
    std::vector<tools::LightOverride> lightSettings;  // --light-set NAME.KEY=JSON, --light NAME=VARIANT
    tools::SceneLighting lighting;  // --key-light spot|point|directional, --ground
    std::optional<double> time;  // --time T: the scene posed at T seconds (Playback.h)
    std::string animate;         // --animate NAME|all: what plays, playing from the start
    std::optional<double> exposureEv100;  // --exposure EV100: the config's exposure replaced
    bool autoExposure = false;            // --exposure auto: metered on the first frame (AutoExposure.h)
    bool help = false;
};

extern const char* const kViewUsage;

// Throws std::invalid_argument with one line naming the flag and the reason.
ViewOptions parseViewOptions(int argc, char** argv);

} // namespace engine_view
