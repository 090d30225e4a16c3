#pragma once
// glTF animations. tinygltf 2.7.0 silently drops a channel it cannot parse (one without
// target.node, say), which would shift every later channel's index in our messages: the
// structure is read from our own parse of the JSON, the keys from the validated accessors.
#include "GltfContext.h"
#include "engine/scene/Animation.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <vector>

namespace engine::gltf {

// Every animation of the document, checked as glTF 2.0 requires: samplers' input and output
// accessors of the right type, key counts that agree, times finite, >= 0 and strictly
// increasing, rotation keys that are not zero quaternions, channels naming an existing
// sampler and node (not one given by matrix), each (node, path) at most once, weights
// channels sized to the node's morph targets. Any breach fails, naming the animation and
// the channel or sampler. A sampler no channel uses is kept empty, with a warning.
std::vector<Animation> readAnimations(const LoadContext& context, const tinygltf::Model& model,
                                      const nlohmann::json& document);

} // namespace engine::gltf
