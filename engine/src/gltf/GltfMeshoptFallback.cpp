#include "GltfMeshoptFallback.h"

namespace engine::gltf {

bool isDatalessFallbackBuffer(const nlohmann::json& buffer) {
    if (!buffer.is_object() || buffer.contains("uri")) return false;
    const auto extensions = buffer.find("extensions");
    if (extensions == buffer.end() || !extensions->is_object()) return false;
    const auto meshopt = extensions->find("EXT_meshopt_compression");
    if (meshopt == extensions->end() || !meshopt->is_object()) return false;
    const auto fallback = meshopt->find("fallback");
    return fallback != meshopt->end() && fallback->is_boolean() && fallback->get<bool>();
}

std::vector<std::uint8_t> withPlaceholderFallbackBuffers(const nlohmann::json& document,
                                                         const GltfContainer& container) {
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array()) return {};
    nlohmann::json rewritten;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        if (!isDatalessFallbackBuffer((*buffers)[i])) continue;
        if (rewritten.is_null()) rewritten = document;
        // One zero byte: the smallest buffer tinygltf accepts (byteLength 0 makes it throw).
        rewritten["buffers"][i] = {{"byteLength", 1}, {"uri", "data:application/octet-stream;base64,AA=="}};
    }
    if (rewritten.is_null()) return {};
    const std::string json = rewritten.dump();
    if (container.binary) return joinGlb(json, container.bin);
    return {json.begin(), json.end()};
}

} // namespace engine::gltf
