#include "AddedLights.h"

#include "JsonEdits.h"

#include "engine/util/Error.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tools {

namespace {

constexpr const char* kPunctual = "KHR_lights_punctual";

const char* typeName(engine::Light::Type type) {
    switch (type) {
    case engine::Light::Type::Directional: return "directional";
    case engine::Light::Type::Spot: return "spot";
    case engine::Light::Type::Point: return "point";
    }
    return "point";
}

nlohmann::json array(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The texts of `values`, each dumped.
std::vector<std::string> dumped(const std::vector<nlohmann::json>& values) {
    std::vector<std::string> texts;
    for (const nlohmann::json& value : values) texts.push_back(value.dump());
    return texts;
}

} // namespace

AddedLight addedLightOf(const engine::Scene& scene, int node, const nlohmann::json& shadow) {
    const engine::Node& placed = scene.nodes.at(node);
    const engine::Light& light = scene.lights.at(placed.light);
    AddedLight added;
    added.light = {{"name", light.name}, {"type", typeName(light.type)}, {"intensity", light.intensity}};
    if (light.color != glm::vec3(1.0f)) added.light["color"] = {light.color.r, light.color.g, light.color.b};
    if (light.range > 0.0 && light.type != engine::Light::Type::Directional) added.light["range"] = light.range;
    if (light.type == engine::Light::Type::Spot)
        added.light["spot"] = {{"innerConeAngle", light.innerConeAngle}, {"outerConeAngle", light.outerConeAngle}};
    if (!shadow.empty()) added.light["extras"] = {{"shadow", shadow}};

    // local = T * R * S: the columns' lengths are the scale, the normalized columns R.
    const glm::dmat4& local = placed.local;
    glm::dmat3 rotation(local);
    glm::dvec3 scale;
    for (int c = 0; c < 3; ++c) {
        scale[c] = glm::length(rotation[c]);
        rotation[c] /= scale[c];
    }
    const glm::dquat q = glm::normalize(glm::quat_cast(rotation));
    added.node = {{"name", placed.name}, {"translation", array(glm::dvec3(local[3]))}, {"rotation", {q.x, q.y, q.z, q.w}}};
    if (glm::any(glm::greaterThan(glm::abs(scale - 1.0), glm::dvec3(1e-12)))) added.node["scale"] = array(scale);
    return added;
}

std::string addLights(const std::string& json, const std::vector<AddedLight>& lights, const std::string& fileName) {
    if (lights.empty()) return json;
    nlohmann::json expected = nlohmann::json::parse(json);
    const JsonSpan root = scanJson(json);
    const int sceneIndex = expected.contains("scene") && expected["scene"].is_number_integer() ? expected["scene"].get<int>() : 0;
    const JsonSpan* scenes = root.member("scenes");
    if (!scenes || scenes->kind != '[' || sceneIndex < 0 || sceneIndex >= static_cast<int>(scenes->items.size()) ||
        scenes->items[sceneIndex].kind != '{')
        engine::throwInputError(fileName, "scenes[" + std::to_string(sceneIndex) + "]",
                                "no scene to add the light to");
    const JsonSpan* nodes = root.member("nodes");
    if (nodes && nodes->kind != '[') engine::throwInputError(fileName, "nodes", "is not an array");
    const JsonSpan* extensions = root.member("extensions");
    const JsonSpan* punctual = extensions && extensions->kind == '{' ? extensions->member(kPunctual) : nullptr;
    const JsonSpan* lightList = punctual && punctual->kind == '{' ? punctual->member("lights") : nullptr;
    if ((extensions && extensions->kind != '{') || (punctual && punctual->kind != '{') ||
        (lightList && lightList->kind != '['))
        engine::throwInputError(fileName, std::string("extensions.") + kPunctual, "is not a list of lights");

    // The new entries and where they go.
    const int firstLight = lightList ? static_cast<int>(lightList->items.size()) : 0;
    const int firstNode = nodes ? static_cast<int>(nodes->items.size()) : 0;
    std::vector<nlohmann::json> newLights, newNodes, newRoots;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        newLights.push_back(lights[i].light);
        nlohmann::json node = lights[i].node;
        node["extensions"][kPunctual] = {{"light", firstLight + static_cast<int>(i)}};
        newNodes.push_back(node);
        newRoots.push_back(firstNode + static_cast<int>(i));
    }
    for (const nlohmann::json& light : newLights) expected["extensions"][kPunctual]["lights"].push_back(light);
    for (const nlohmann::json& node : newNodes) expected["nodes"].push_back(node);
    for (const nlohmann::json& index : newRoots) expected["scenes"][sceneIndex]["nodes"].push_back(index);

    std::vector<JsonEdit> edits;
    const nlohmann::json lightArray(newLights), nodeArray(newNodes), rootArray(newRoots);
    if (lightList) edits.push_back(appendItems(*lightList, dumped(newLights)));
    else if (punctual) edits.push_back(appendMember(*punctual, "lights", lightArray.dump()));
    else if (extensions)
        edits.push_back(appendMember(*extensions, kPunctual, nlohmann::json{{"lights", lightArray}}.dump()));
    else edits.push_back(appendMember(root, "extensions", nlohmann::json{{kPunctual, {{"lights", lightArray}}}}.dump()));

    edits.push_back(nodes ? appendItems(*nodes, dumped(newNodes)) : appendMember(root, "nodes", nodeArray.dump()));

    const JsonSpan& scene = scenes->items[sceneIndex];
    const JsonSpan* roots = scene.member("nodes");
    if (roots && roots->kind != '[')
        engine::throwInputError(fileName, "scenes[" + std::to_string(sceneIndex) + "].nodes", "is not an array");
    edits.push_back(roots ? appendItems(*roots, dumped(newRoots)) : appendMember(scene, "nodes", rootArray.dump()));

    const JsonSpan* used = root.member("extensionsUsed");
    const bool listed = expected.contains("extensionsUsed") && expected["extensionsUsed"].is_array() &&
                        std::find(expected["extensionsUsed"].begin(), expected["extensionsUsed"].end(), kPunctual) !=
                            expected["extensionsUsed"].end();
    if (!listed) {
        if (used && used->kind != '[') engine::throwInputError(fileName, "extensionsUsed", "is not an array");
        edits.push_back(used ? appendItems(*used, {nlohmann::json(kPunctual).dump()})
                             : appendMember(root, "extensionsUsed", nlohmann::json::array({kPunctual}).dump()));
        expected["extensionsUsed"].push_back(kPunctual);
    }

    const std::string out = applyJsonEdits(json, std::move(edits));
    if (nlohmann::json::parse(out) != expected)
        throw std::logic_error("adding lights to " + fileName + " changed more than the lights, nodes and roots");
    return out;
}

} // namespace tools
