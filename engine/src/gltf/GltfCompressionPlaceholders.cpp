#include "GltfCompressionPlaceholders.h"

#include <algorithm>

namespace engine::gltf {

namespace {

// object[key] when it is an object, else nullptr.
const nlohmann::json* objectMember(const nlohmann::json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto found = object.find(key);
    return found != object.end() && found->is_object() ? &*found : nullptr;
}

// document[array][index] when the index is a number in range and the element an object.
nlohmann::json* elementAt(nlohmann::json& document, const char* array, const nlohmann::json& index) {
    if (!index.is_number_unsigned()) return nullptr;
    const auto list = document.find(array);
    if (list == document.end() || !list->is_array() || index.get<std::uint64_t>() >= list->size()) return nullptr;
    nlohmann::json& element = (*list)[index.get<std::size_t>()];
    return element.is_object() ? &element : nullptr;
}

bool replaceFallbackBuffers(nlohmann::json& document) {
    bool replaced = false;
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array()) return false;
    for (nlohmann::json& buffer : *buffers) {
        if (!isDatalessFallbackBuffer(buffer)) continue;
        // One zero byte: the smallest buffer tinygltf accepts (byteLength 0 makes it throw).
        buffer = {{"byteLength", 1}, {"uri", "data:application/octet-stream;base64,AA=="}};
        replaced = true;
    }
    return replaced;
}

bool giveDracoIndicesAView(nlohmann::json& document) {
    bool replaced = false;
    const auto meshes = document.find("meshes");
    if (meshes == document.end() || !meshes->is_array()) return false;
    for (const nlohmann::json& mesh : *meshes) {
        const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
        for (const nlohmann::json& primitive : *primitives) {
            const nlohmann::json* extensions = objectMember(primitive, "extensions");
            const nlohmann::json* draco = extensions ? objectMember(*extensions, "KHR_draco_mesh_compression") : nullptr;
            if (!draco || !primitive.contains("indices") || !draco->contains("bufferView")) continue;
            nlohmann::json* accessor = elementAt(document, "accessors", primitive["indices"]);
            const nlohmann::json& view = (*draco)["bufferView"];
            if (!accessor || accessor->contains("bufferView") || !elementAt(document, "bufferViews", view)) continue;
            (*accessor)["bufferView"] = view;
            replaced = true;
        }
    }
    return replaced;
}

} // namespace

bool isDatalessFallbackBuffer(const nlohmann::json& buffer) {
    if (!buffer.is_object() || buffer.contains("uri")) return false;
    const nlohmann::json* extensions = objectMember(buffer, "extensions");
    const nlohmann::json* meshopt = extensions ? objectMember(*extensions, "EXT_meshopt_compression") : nullptr;
    if (!meshopt) return false;
    const auto fallback = meshopt->find("fallback");
    return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

std::vector<std::uint8_t> withCompressionPlaceholders(const nlohmann::json& document, const GltfContainer& container) {
    // A file using either extension must list it in extensionsUsed (glTF 2.0 3.12); any
    // other file is passed on without copying its document.
    const auto used = document.find("extensionsUsed");
    if (used == document.end() || !used->is_array()) return {};
    const bool compressed = std::any_of(used->begin(), used->end(), [](const nlohmann::json& name) {
        return name == "EXT_meshopt_compression" || name == "KHR_draco_mesh_compression";
    });
    if (!compressed) return {};
    nlohmann::json shown = document;
    const bool fallbacks = replaceFallbackBuffers(shown);
    const bool dracoIndices = giveDracoIndicesAView(shown);
    if (!fallbacks && !dracoIndices) return {};
    const std::string json = shown.dump();
    if (container.binary) return joinGlb(json, container.bin);
    return {json.begin(), json.end()};
}

} // namespace engine::gltf
