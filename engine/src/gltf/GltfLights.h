#pragma once
// KHR_lights_punctual. tinygltf 2.7.0 parses the lights but checks no value (and turns a
// wrongly typed field into its default silently), and its Node has no `light` field: the
// lights are read from our own parse of the JSON, each field validated, and the node's
// reference from node.extensions.
#include "GltfContext.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace engine::gltf {

// The document's lights (none when the extension is absent), validated field by field;
// each keeps its "extras" (e.g. the per-light shadow settings) as JSON for the plugins.
std::vector<Light> readPunctualLights(const LoadContext& context, const nlohmann::json& document);

// The light placed by node `nodeIndex`, -1 when none. The index itself is range-checked by
// validateReferences.
int nodeLightIndex(const LoadContext& context, const tinygltf::Node& node, std::size_t nodeIndex);

} // namespace engine::gltf
