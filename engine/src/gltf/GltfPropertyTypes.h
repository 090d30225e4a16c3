#pragma once
// JSON types of the glTF properties this loader consumes. tinygltf 2.7.0 silently skips a
// property of the wrong type (a "primitives" object instead of an array makes a mesh
// vanish, a string index becomes -1): such a file is refused here instead, naming the
// property.
#include "GltfContext.h"

#include <nlohmann/json.hpp>

namespace engine::gltf {

void checkPropertyTypes(const LoadContext& context, const nlohmann::json& document);

} // namespace engine::gltf
