#pragma once
// The glTF JSON text, checked and parsed by us before tinygltf parses it again: tinygltf
// 2.7.0 walks nested values recursively (about 20 000 levels overflow the stack), and
// URIs must be vetted before tinygltf opens them. Our parse also keeps what tinygltf
// flattens (light extras as JSON, exact value types).
#include "GltfContext.h"

#include <nlohmann/json.hpp>

#include <string_view>

namespace engine::gltf {

// Refuses arrays/objects nested deeper than options.maxJsonDepth, by a linear scan that
// itself uses no recursion. Must run before any JSON parser sees the text.
void checkJsonNesting(const LoadContext& context, std::string_view jsonText);

// Parses the (nesting-checked) text; malformed JSON is an InputError with its position.
nlohmann::json parseJsonDocument(const LoadContext& context, std::string_view jsonText);

} // namespace engine::gltf
