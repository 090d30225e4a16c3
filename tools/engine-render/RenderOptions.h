#pragma once
// engine-render's command line (the contract the README's "Rendering a scene" documents).
#include "LightOverrides.h"
#include "OptionValues.h"
#include "SceneLighting.h"
#include "SettingOverrides.h"

#include "engine/scene/Scene.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

struct RenderOptions {
    std::string config;  // empty: tools::defaultConfigPath()
    std::string scene;
    std::string out;
    int width = tools::kDefaultImageWidth, height = tools::kDefaultImageHeight;
    std::string camera;  // a name, else a number from --list; empty: first glTF camera
    // --light-set NAME.KEY=JSON and --light NAME=VARIANT, in the order given
    std::vector<tools::LightOverride> lightSettings;
    std::vector<std::pair<std::string, std::string>> shadowMasks;    // --shadow-mask NAME=FILE
    std::vector<std::pair<std::string, std::string>> shadowMaps;     // --shadow-map NAME=FILE
    std::vector<std::pair<std::string, std::string>> comparisons;    // --shadow-compare NAME=FILE
    // --truth-mask NAME=FILE: the truth --truth scores that light against (implies --truth)
    std::vector<std::pair<std::string, std::string>> truthMasks;
    // --texel-density NAME=FILE: the heat map of a map texel's size on screen (truth/TexelDensityImage.h)
    std::vector<std::pair<std::string, std::string>> texelDensities;
    // --light-tiles FILE: the clustered lit pass's tile lists as a heat map (LightTileImage.h)
    std::string lightTiles;
    int frames = 1;
    int warmup = 1;  // at least this many untimed frames first (Renderer::warmUp): llvmpipe compiles at first draw
    std::vector<tools::SettingOverride> pluginSettings;  // --set PLUGIN.KEY=JSON, each key once
    tools::SceneLighting lighting;  // --key-light spot|point|directional, --ground
    std::string orbitLight;   // --orbit-light NAME: turn that light 2 degrees per frame
    bool orbitCamera = false; // --orbit-camera: turn the camera 2 degrees per frame
    // --time T: pose the scene's animations at T seconds (every frame, unless --animate);
    // --animate NAME|all: play those animations, frame i at T + i / --fps. Neither: rest pose.
    std::optional<double> time;
    std::string animate;
    std::optional<double> fps;
    bool truth = false;       // --truth: per-light error against ray-traced shadows
    std::optional<double> exposureEv100;  // --exposure EV100: the config's exposure replaced
    bool autoExposure = false;            // --exposure auto: metered on the first frame (AutoExposure.h)
    std::optional<int> msaa;              // --msaa N: the config's renderer.msaa replaced
    bool list = false;        // --list: print the scene's cameras and lights, render nothing
    std::string stats;      // JSON
    std::string graphDot;   // graphviz of the last frame's compiled graph
    bool help = false;
};

extern const char* const kRenderUsage;

// Throws std::invalid_argument with one line naming the flag and the reason.
RenderOptions parseRenderOptions(int argc, char** argv);

// Every file the run will write (--out, the masks, truth masks, maps, comparisons and texel
// densities, --stats, --graph-dot).
std::vector<std::string> outputFiles(const RenderOptions& options);
