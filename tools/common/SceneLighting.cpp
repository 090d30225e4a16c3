#include "SceneLighting.h"

#include "OptionValues.h"

#include "engine/scene/SceneEdit.h"
#include "engine/scene/SceneNames.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace tools {

bool parseSceneLightingFlag(SceneLighting& lighting, const std::string& flag, const std::string& value) {
    if (flag == "--key-light") lighting.keyLight = parseLightType(flag, value);
    else if (flag == "--key-light-angles") {
        const std::vector<double> angles = parseNumberList(flag, value, -180.0, 180.0);
        if (angles.size() != 2 || angles[1] <= 0.0 || angles[1] > 90.0)
            throw std::invalid_argument(flag + " " + value +
                                        ": give AZIMUTH,ELEVATION in degrees, azimuth in [-180, 180] from the "
                                        "framing view toward its right, elevation in (0, 90]");
        lighting.keyLightAngles = {angles[0], angles[1]};
    } else if (flag == kGroundFlag) lighting.ground = true;
    else return false;
    return true;
}

namespace {

std::string point(const glm::dvec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    return text;
}

} // namespace

std::string describeKeyLight(const engine::Scene& scene, int node) {
    const engine::Node& placed = scene.nodes.at(node);
    const engine::Light& light = scene.lights.at(placed.light);
    const glm::dvec3 position(placed.world[3]);
    const glm::dvec3 target = scene.worldBounds.empty() ? position : scene.worldBounds.center();
    std::string text = "key light: " + std::string(engine::toString(light.type)) + " \"" + light.name + "\" ";
    if (light.type == engine::Light::Type::Directional)
        text += "shining from " + point(position) + " towards " + point(target);
    else
        text += "at " + point(position) + " aimed at " + point(target);
    if (light.type == engine::Light::Type::Spot) {
        char cone[64];
        std::snprintf(cone, sizeof cone, ", cone %.1f deg", light.outerConeAngle * 2.0 * 180.0 / M_PI);
        text += cone;
    }
    return text;
}

StagedScene stageScene(engine::Scene& scene, const std::string& sceneFile, const SceneLighting& lighting) {
    StagedScene staged;
    if (lighting.keyLight) {
        // Described before the ground exists: the light aims at the model's centre.
        const int node = engine::addKeyLight(scene, *lighting.keyLight, "key_light", lighting.keyLightAngles);
        staged.notes.push_back(describeKeyLight(scene, node));
    }
    if (lighting.ground) {
        engine::addGround(scene);
        const engine::MeshInstance& ground = scene.meshInstances.back();
        staged.notes.push_back("ground: " + point(ground.worldBounds.min) + " to " + point(ground.worldBounds.max) +
                               " (receives shadows, casts none)");
    }
    if (scene.lightInstances.empty())
        staged.warnings.push_back(sceneFile + ": the scene has no lights: ambient only, no shadows "
                                  "(--key-light spot|point|directional adds one, --ground a floor to catch its shadow)");
    return staged;
}

} // namespace tools
