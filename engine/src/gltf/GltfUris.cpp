// Public face of the loader's URI checks (engine/gltf/GltfUris.h): the same functions the
// loader calls, so the two cannot drift apart.
#include "engine/gltf/GltfUris.h"

#include "GltfFileAccess.h"

namespace engine {

bool isGltfDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string gltfExternalUriProblem(const std::string& uri, const std::filesystem::path& sceneFolder,
                                   std::uint64_t maxBytes) {
    std::error_code error;
    const std::filesystem::path real = std::filesystem::canonical(sceneFolder, error);
    if (error) return "the scene's folder " + sceneFolder.string() + " cannot be resolved: " + error.message();
    return gltf::checkExternalUri(uri, real, maxBytes);
}

bool decodeGltfUri(const std::string& uri, std::string& relativePath) {
    return gltf::decodeUriLikeTinygltf(uri, relativePath);
}

} // namespace engine
