#pragma once
// The loader's rule for the files a glTF scene refers to (buffers and images by URI), for
// tools that copy or embed those files (tools/common/SaveSettings): they vet a URI with the
// very checks the loader applies before it reads (GltfFileAccess.h), so a file a tool
// copies or embeds is one the loader would have read, and a copy placed at the same
// relative path resolves from the copied scene as the original did.
#include <cstdint>
#include <filesystem>
#include <string>

namespace engine {

// Whether `uri` is a data: URI (its bytes are inline, no file).
bool isGltfDataUri(const std::string& uri);

// Why the loader would refuse the non-data `uri` of a scene whose file is in `sceneFolder`
// (a scheme, an absolute path, `..`, a backslash, a malformed escape, no such regular file,
// a real path outside the folder, more than maxBytes), or "" when it would read it.
std::string gltfExternalUriProblem(const std::string& uri, const std::filesystem::path& sceneFolder,
                                   std::uint64_t maxBytes);

// The relative path `uri` names, its percent escapes decoded as the loader decodes them
// (tinygltf 2.7.0 also reads '+' as a space). False for a malformed escape.
bool decodeGltfUri(const std::string& uri, std::string& relativePath);

} // namespace engine
