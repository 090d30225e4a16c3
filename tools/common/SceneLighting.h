#pragma once
// Lighting a scene that brings none (most sample files), the same way in every tool
// (engine-render, engine-view, shadowmap-bench): --key-light adds a light placed from the
// scene's bounds (engine::addKeyLight), --ground adds a receiving ground under the model
// (engine::addGround), the tool prints where the key light went, and a scene left without
// any light gets a warning that says why it renders ambient only.
#include "engine/scene/Scene.h"
#include "engine/scene/SceneEdit.h"

#include <optional>
#include <string>
#include <vector>

namespace tools {

struct SceneLighting {
    std::optional<engine::Light::Type> keyLight;  // --key-light spot|point|directional
    engine::KeyLightAngles keyLightAngles;        // --key-light-angles AZIMUTH,ELEVATION
    bool ground = false;                          // --ground
};

// The flag that takes no value (for parseFlags' switch list).
inline constexpr const char* kGroundFlag = "--ground";

// Takes --key-light VALUE, --key-light-angles AZIMUTH,ELEVATION (degrees, SceneEdit.h's
// KeyLightAngles) and --ground into `lighting`; false for any other flag.
bool parseSceneLightingFlag(SceneLighting& lighting, const std::string& flag, const std::string& value);

// What stageScene did, for the tool to print.
struct StagedScene {
    std::vector<std::string> notes;     // "key light: spot \"key_light\" at (…) aimed at (…), …"
    std::vector<std::string> warnings;  // the scene has no light
};

// Adds the key light (first, placed from the model's bounds), then the ground. A scene that
// ends up without a light gets a warning naming the file and --key-light.
StagedScene stageScene(engine::Scene& scene, const std::string& sceneFile, const SceneLighting& lighting);

// The key light's place in words: type, name, position, target, and a spot's cone.
std::string describeKeyLight(const engine::Scene& scene, int node);

} // namespace tools
