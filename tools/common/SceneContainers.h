#pragma once
// A scene's JSON moved between glTF's two containers (glTF 2.0, "Binary glTF Layout"), for
// SaveSettings.h when a scene is saved as the other one. The document is rewritten as
// nlohmann::ordered_json (members keep their order; spacing and number spelling are
// nlohmann's), since the buffer layout changes anyway.
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>

namespace tools {

// A .glb's chunks: the JSON text and the BIN payload (empty when the file has none).
struct GlbChunks {
    std::string json;
    std::string bin;
};

// Splits a .glb's bytes; throws InputError naming `fileName` when the layout is broken.
GlbChunks splitGlb(const std::string& bytes, const std::string& fileName);

// The .glb file of `json` and `bin` (BIN chunk left out when empty), the JSON chunk padded
// with spaces and the BIN chunk with zeros to 4 bytes, as the spec asks.
std::string joinGlb(const std::string& json, const std::string& bin);

// Reads the file a non-data URI names (already vetted by the caller); `object` names the
// buffer or image for messages, e.g. "buffers[0]".
using ExternalFileReader = std::function<std::string(const std::string& object, const std::string& uri)>;

// A .gltf's document as a .glb: every buffer with data (external file or data: URI) is
// merged into buffers[0], the GLB-stored buffer without uri, each starting at a multiple of
// 4 bytes (glTF's largest component is 4 bytes, so every accessor stays aligned); the
// bufferViews (and EXT_meshopt_compression's buffer references) are pointed into it; images
// with a URI become bufferView images with a mimeType (theirs, else from their first bytes,
// else from the file name). Buffers without data (EXT_meshopt_compression fallbacks) stay
// separate. Throws InputError naming `fileName` and the object for what cannot be embedded.
std::string gltfToGlb(nlohmann::ordered_json document, const ExternalFileReader& read, const std::string& fileName);

// The bytes of buffers[0] when it is the GLB-stored buffer (no uri, data in BIN), else
// nullopt. Throws InputError when the BIN chunk is missing or shorter than its byteLength.
std::optional<std::string> glbStoredBuffer(const nlohmann::json& document, const std::string& bin,
                                           const std::string& fileName);

// A .glb's document as a .gltf whose GLB-stored buffer (if any) is the file `binUri`
// (relative to the .gltf); 2-space indented, as a .gltf is read by people too.
std::string glbToGltf(nlohmann::ordered_json document, const std::string& binUri);

// `relativePath` as a URI the loader decodes back to it: everything but unreserved
// characters and '/' percent-encoded (tinygltf reads a literal '+' as a space).
std::string encodeUriPath(const std::string& relativePath);

// "image/png", "image/jpeg", "image/webp" or "image/ktx2" from the first bytes, else from
// the name's extension; "" when neither tells.
std::string imageMediaType(const std::string& bytes, const std::string& name);

} // namespace tools
