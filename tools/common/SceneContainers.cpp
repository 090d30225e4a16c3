#include "SceneContainers.h"

#include "engine/gltf/GltfUris.h"
#include "engine/util/Error.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace tools {

namespace {

constexpr std::size_t kHeaderBytes = 12, kChunkHeaderBytes = 8;

std::uint32_t readU32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

void appendU32(std::string& bytes, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((value >> (8 * i)) & 0xFF);
}

std::string indexed(const char* list, std::size_t index) {
    return std::string(list) + "[" + std::to_string(index) + "]";
}

// The loader's marker of a buffer that has no bytes of its own (GltfCompressionPlaceholders.h).
template <typename Json>
bool isDatalessFallbackBuffer(const Json& buffer) {
    if (buffer.contains("uri")) return false;
    const auto extensions = buffer.find("extensions");
    if (extensions == buffer.end() || !extensions->is_object()) return false;
    const auto meshopt = extensions->find("EXT_meshopt_compression");
    return meshopt != extensions->end() && meshopt->is_object() && meshopt->value("fallback", false) == true;
}

// The bytes of a base64 data URI; decoding stops at the first character outside the
// alphabet ('=' padding included), as the loader's decoder (tinygltf) does.
std::string decodeDataUri(const std::string& uri, const std::string& fileName, const std::string& object) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0)
        engine::throwInputError(fileName, object, "its data URI is not base64: cannot embed it");
    std::string bytes;
    std::uint32_t bits = 0;
    int count = 0;
    for (std::size_t i = comma + 1; i < uri.size(); ++i) {
        const char c = uri[i];
        int value = -1;
        if (c >= 'A' && c <= 'Z') value = c - 'A';
        else if (c >= 'a' && c <= 'z') value = c - 'a' + 26;
        else if (c >= '0' && c <= '9') value = c - '0' + 52;
        else if (c == '+') value = 62;
        else if (c == '/') value = 63;
        else break;
        bits = (bits << 6) | static_cast<std::uint32_t>(value);
        if (++count == 4) {
            bytes += static_cast<char>((bits >> 16) & 0xFF);
            bytes += static_cast<char>((bits >> 8) & 0xFF);
            bytes += static_cast<char>(bits & 0xFF);
            bits = 0;
            count = 0;
        }
    }
    if (count == 2) bytes += static_cast<char>((bits >> 4) & 0xFF);
    if (count == 3) {
        bytes += static_cast<char>((bits >> 10) & 0xFF);
        bytes += static_cast<char>((bits >> 2) & 0xFF);
    }
    return bytes;
}

std::string uriBytes(const std::string& uri, const ExternalFileReader& read, const std::string& fileName,
                     const std::string& object) {
    return engine::isGltfDataUri(uri) ? decodeDataUri(uri, fileName, object) : read(object, uri);
}

void alignTo4(std::string& bin) { bin.append((4 - bin.size() % 4) % 4, '\0'); }

std::string mediaTypeOfDataUri(const std::string& uri) {
    const std::size_t end = uri.find_first_of(";,");
    return end == std::string::npos ? "" : uri.substr(5, end - 5);
}

// Points a buffer reference (`holder`["buffer"], with its "byteOffset") at the merged layout.
void remapBufferReference(nlohmann::ordered_json& holder, const std::vector<long>& newIndex,
                          const std::vector<std::uint64_t>& base, const std::vector<bool>& merged,
                          const std::string& fileName, const std::string& object) {
    const auto buffer = holder.find("buffer");
    if (buffer == holder.end() || !buffer->is_number_unsigned() || buffer->get<std::uint64_t>() >= newIndex.size())
        engine::throwInputError(fileName, object, "buffer is missing or not the index of a buffer");
    const std::size_t old = buffer->get<std::size_t>();
    *buffer = newIndex[old];
    if (!merged[old]) return;
    const auto offset = holder.find("byteOffset");
    const std::uint64_t oldOffset = offset != holder.end() && offset->is_number_unsigned() ? offset->get<std::uint64_t>() : 0;
    holder["byteOffset"] = base[old] + oldOffset;
}

} // namespace

GlbChunks splitGlb(const std::string& bytes, const std::string& fileName) {
    if (bytes.size() < kHeaderBytes + kChunkHeaderBytes || bytes.compare(0, 4, "glTF") != 0)
        engine::throwInputError(fileName, "GLB header", "not a GLB file (no 'glTF' magic or too short)");
    const std::size_t jsonLength = readU32(bytes, 12);
    if (bytes.compare(16, 4, "JSON") != 0 || kHeaderBytes + kChunkHeaderBytes + jsonLength > bytes.size())
        engine::throwInputError(fileName, "GLB", "the first chunk is not a JSON chunk");
    GlbChunks chunks;
    chunks.json = bytes.substr(kHeaderBytes + kChunkHeaderBytes, jsonLength);
    const std::size_t binAt = kHeaderBytes + kChunkHeaderBytes + jsonLength;
    if (binAt + kChunkHeaderBytes <= bytes.size() && bytes.compare(binAt + 4, 4, std::string("BIN\0", 4)) == 0) {
        const std::size_t binLength = readU32(bytes, binAt);
        if (binAt + kChunkHeaderBytes + binLength > bytes.size())
            engine::throwInputError(fileName, "GLB chunk 1 (BIN)", "runs past the end of the file");
        chunks.bin = bytes.substr(binAt + kChunkHeaderBytes, binLength);
    }
    return chunks;
}

std::string joinGlb(const std::string& json, const std::string& bin) {
    std::string bytes = "glTF";
    appendU32(bytes, 2);
    appendU32(bytes, 0);  // total length, filled in below
    const auto appendChunk = [&bytes](const std::string& payload, const char* type, char pad) {
        const std::size_t padding = (4 - payload.size() % 4) % 4;
        appendU32(bytes, static_cast<std::uint32_t>(payload.size() + padding));
        bytes.append(type, 4);
        bytes += payload;
        bytes.append(padding, pad);
    };
    appendChunk(json, "JSON", ' ');
    if (!bin.empty()) appendChunk(bin, "BIN\0", '\0');
    const std::uint32_t total = static_cast<std::uint32_t>(bytes.size());
    for (int i = 0; i < 4; ++i) bytes[8 + i] = static_cast<char>((total >> (8 * i)) & 0xFF);
    return bytes;
}

std::string gltfToGlb(nlohmann::ordered_json document, const ExternalFileReader& read, const std::string& fileName) {
    std::string bin;
    nlohmann::ordered_json buffers = document.value("buffers", nlohmann::ordered_json::array());
    if (!buffers.is_array()) engine::throwInputError(fileName, "buffers", "is not an array");
    std::vector<bool> merged(buffers.size(), false);
    std::vector<std::uint64_t> base(buffers.size(), 0);
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const std::string object = indexed("buffers", i);
        const nlohmann::ordered_json& buffer = buffers[i];
        if (!buffer.is_object()) engine::throwInputError(fileName, object, "is not an object");
        if (isDatalessFallbackBuffer(buffer)) continue;
        const auto uri = buffer.find("uri");
        if (uri == buffer.end() || !uri->is_string())
            engine::throwInputError(fileName, object, "has no uri: a .gltf's buffer needs one to hold any bytes");
        const auto byteLength = buffer.find("byteLength");
        if (byteLength == buffer.end() || !byteLength->is_number_unsigned())
            engine::throwInputError(fileName, object, "byteLength is missing or not a non-negative integer");
        const std::uint64_t length = byteLength->get<std::uint64_t>();
        std::string bytes = uriBytes(uri->get<std::string>(), read, fileName, object);
        if (bytes.size() < length)
            engine::throwInputError(fileName, object, "holds " + std::to_string(bytes.size()) +
                                                          " bytes, byteLength says " + std::to_string(length));
        alignTo4(bin);
        base[i] = bin.size();
        bin.append(bytes, 0, length);
        merged[i] = true;
    }

    std::vector<std::pair<std::size_t, nlohmann::ordered_json>> imageViews;  // image index, its new bufferView
    if (document.contains("images")) {
        nlohmann::ordered_json& images = document["images"];
        if (!images.is_array()) engine::throwInputError(fileName, "images", "is not an array");
        for (std::size_t i = 0; i < images.size(); ++i) {
            const std::string object = indexed("images", i);
            nlohmann::ordered_json& image = images[i];
            if (!image.is_object()) engine::throwInputError(fileName, object, "is not an object");
            const auto uri = image.find("uri");
            if (uri == image.end()) continue;  // already a bufferView image
            if (!uri->is_string()) engine::throwInputError(fileName, object, "uri is not a string");
            const std::string text = uri->get<std::string>();
            const std::string bytes = uriBytes(text, read, fileName, object);
            if (bytes.empty()) engine::throwInputError(fileName, object, "the image is empty: nothing to embed");
            std::string mediaType = image.contains("mimeType") && image["mimeType"].is_string()
                                        ? image["mimeType"].get<std::string>()
                                        : imageMediaType(bytes, engine::isGltfDataUri(text) ? "" : text);
            if (mediaType.empty() && engine::isGltfDataUri(text)) mediaType = mediaTypeOfDataUri(text);
            if (mediaType.rfind("image/", 0) != 0)
                engine::throwInputError(fileName, object, "neither its first bytes nor its name say it is PNG, JPEG, "
                                                          "WebP or KTX2: a GLB's image needs a mimeType");
            alignTo4(bin);
            imageViews.emplace_back(i, nlohmann::ordered_json{{"buffer", 0}, {"byteOffset", bin.size()},
                                                              {"byteLength", bytes.size()}});
            bin += bytes;
            image.erase("uri");
            image["mimeType"] = mediaType;
        }
    }

    // buffers[0] is the GLB-stored buffer when there are bytes; data-less buffers follow.
    std::vector<long> newIndex(buffers.size(), 0);
    nlohmann::ordered_json newBuffers = nlohmann::ordered_json::array();
    if (!bin.empty()) newBuffers.push_back(nlohmann::ordered_json::object({{"byteLength", bin.size()}}));
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        if (merged[i]) continue;
        newIndex[i] = static_cast<long>(newBuffers.size());
        newBuffers.push_back(buffers[i]);
    }

    if (document.contains("bufferViews")) {
        nlohmann::ordered_json& views = document["bufferViews"];
        if (!views.is_array()) engine::throwInputError(fileName, "bufferViews", "is not an array");
        for (std::size_t v = 0; v < views.size(); ++v) {
            const std::string object = indexed("bufferViews", v);
            nlohmann::ordered_json& view = views[v];
            if (!view.is_object()) engine::throwInputError(fileName, object, "is not an object");
            remapBufferReference(view, newIndex, base, merged, fileName, object);
            if (view.contains("extensions") && view["extensions"].is_object() &&
                view["extensions"].contains("EXT_meshopt_compression"))
                remapBufferReference(view["extensions"]["EXT_meshopt_compression"], newIndex, base, merged, fileName,
                                     object + ".extensions.EXT_meshopt_compression");
        }
    }
    for (auto& [image, view] : imageViews) {
        nlohmann::ordered_json& views = document["bufferViews"];
        if (views.is_null()) views = nlohmann::ordered_json::array();
        document["images"][image]["bufferView"] = views.size();
        views.push_back(std::move(view));
    }
    if (newBuffers.empty()) document.erase("buffers");
    else document["buffers"] = std::move(newBuffers);
    alignTo4(bin);  // the chunk is padded anyway; buffers[0].byteLength may be up to 3 bytes less
    return joinGlb(document.dump(), bin);
}

std::optional<std::string> glbStoredBuffer(const nlohmann::json& document, const std::string& bin,
                                           const std::string& fileName) {
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array() || buffers->empty() || !(*buffers)[0].is_object())
        return std::nullopt;
    const nlohmann::json& buffer = (*buffers)[0];
    if (buffer.contains("uri") || isDatalessFallbackBuffer(buffer)) return std::nullopt;
    const auto byteLength = buffer.find("byteLength");
    if (byteLength == buffer.end() || !byteLength->is_number_unsigned())
        engine::throwInputError(fileName, "buffers[0]", "byteLength is missing or not a non-negative integer");
    const std::uint64_t length = byteLength->get<std::uint64_t>();
    if (length > bin.size())
        engine::throwInputError(fileName, "buffers[0]", "byteLength " + std::to_string(length) +
                                                            " is more than the GLB BIN chunk holds (" +
                                                            std::to_string(bin.size()) + " bytes)");
    return bin.substr(0, length);
}

std::string glbToGltf(nlohmann::ordered_json document, const std::string& binUri) {
    if (document.contains("buffers") && document["buffers"].is_array() && !document["buffers"].empty()) {
        nlohmann::ordered_json& buffer = document["buffers"][0];
        if (buffer.is_object() && !buffer.contains("uri") && !isDatalessFallbackBuffer(buffer)) buffer["uri"] = binUri;
    }
    return document.dump(2) + "\n";
}

std::string encodeUriPath(const std::string& relativePath) {
    static const char* const kHex = "0123456789ABCDEF";
    std::string uri;
    for (const char c : relativePath) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            uri += c;
        } else {
            uri += '%';
            uri += kHex[byte >> 4];
            uri += kHex[byte & 0xF];
        }
    }
    return uri;
}

std::string imageMediaType(const std::string& bytes, const std::string& name) {
    if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return "image/png";
    if (bytes.compare(0, 3, "\xFF\xD8\xFF") == 0) return "image/jpeg";
    if (bytes.size() >= 12 && bytes.compare(0, 4, "RIFF") == 0 && bytes.compare(8, 4, "WEBP") == 0) return "image/webp";
    if (bytes.compare(0, 12, "\xABKTX 20\xBB\r\n\x1a\n") == 0) return "image/ktx2";
    std::string extension = name.substr(std::min(name.size(), name.rfind('.') == std::string::npos ? name.size()
                                                                                                    : name.rfind('.')));
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png") return "image/png";
    if (extension == ".jpg" || extension == ".jpeg") return "image/jpeg";
    if (extension == ".webp") return "image/webp";
    if (extension == ".ktx2") return "image/ktx2";
    return "";
}

} // namespace tools
