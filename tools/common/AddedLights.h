#pragma once
// Lights a tool adds to a scene file: shadowmap-tune --key-light tunes the key light of a
// scene that brings none, and the tuned file must hold that light (placed and set as it was
// measured), or the settings it chose would apply to nothing.
//
// Written in place like SaveSettings.h's edits: the light is appended to
// KHR_lights_punctual.lights (the extension object and its "extensionsUsed" entry created
// when missing), a node placing it to "nodes", and that node to the displayed scene's root
// nodes; every other byte stays.
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tools {

struct AddedLight {
    nlohmann::json light;  // a KHR_lights_punctual light object
    nlohmann::json node;   // the node that places it (its "extensions" are filled in when written)
};

// Node `node` of `scene` (a root node with a light) as glTF: the light's name, type, color,
// intensity, range and spot cone; the node's name, translation and rotation (and scale
// when not 1) from its local matrix; extras.shadow = `shadow` unless empty.
AddedLight addedLightOf(const engine::Scene& scene, int node, const nlohmann::json& shadow);

// The JSON text with `lights` added. Throws InputError naming `fileName` when the file has
// no scene to add them to, and std::logic_error if the result does not parse to the
// original document with the additions (our bug).
std::string addLights(const std::string& json, const std::vector<AddedLight>& lights, const std::string& fileName);

} // namespace tools
