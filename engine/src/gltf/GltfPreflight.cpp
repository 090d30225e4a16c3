#include "GltfPreflight.h"

#include "GltfFileAccess.h"
#include "GltfCompressionPlaceholders.h"
#include "GltfPropertyTypes.h"
#include "GltfValidation.h"

#include <array>
#include <cctype>

namespace engine::gltf {

namespace {

constexpr std::array kSupportedExtensions{"KHR_lights_punctual",        "KHR_texture_transform",
                                          "KHR_lights_shadows",         "KHR_draco_mesh_compression",
                                          "EXT_meshopt_compression",    "KHR_mesh_quantization",
                                          "KHR_materials_emissive_strength"};

// "KHR_lights_punctual, KHR_texture_transform, ...": the list refusals quote.
std::string supportedExtensionList() {
    std::string list;
    for (const char* name : kSupportedExtensions) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

void checkAssetVersion(const LoadContext& context, const nlohmann::json& document) {
    const auto asset = document.find("asset");
    if (asset == document.end() || !asset->is_object())
        context.fail("asset", "missing (glTF 2.0 requires asset.version)");
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        context.fail("asset", "version is missing or not a string");
    const std::string text = version->get<std::string>();
    if (text.rfind("2.", 0) != 0)
        context.fail("asset", "version " + quoted(text) + " is not supported (only glTF 2.x)");
}

// A list of extension names, or a clear error when the file spells it otherwise.
std::vector<std::string> extensionNames(const LoadContext& context, const nlohmann::json& document,
                                        const char* key) {
    std::vector<std::string> names;
    const auto list = document.find(key);
    if (list == document.end()) return names;
    if (!list->is_array()) context.fail(key, "is not an array");
    for (const auto& name : *list) {
        if (!name.is_string()) context.fail(key, "holds a value that is not a string");
        names.push_back(name.get<std::string>());
    }
    return names;
}

void checkExtensions(const LoadContext& context, const nlohmann::json& document) {
    for (const std::string& name : extensionNames(context, document, "extensionsRequired"))
        if (!isSupportedExtension(name))
            context.fail("extensionsRequired", quoted(name) + " is not supported (supported: " + supportedExtensionList() + ")");
    for (const std::string& name : extensionNames(context, document, "extensionsUsed"))
        if (!isSupportedExtension(name))
            context.warn("extensionsUsed", quoted(name) + " is not supported and is ignored");
}

// How many bytes tinygltf's base64 decoder will produce: it stops at '=' or at the first
// character outside the alphabet, and a trailing group of k characters gives k-1 bytes.
std::uint64_t base64DecodedSize(std::string_view payload) {
    std::uint64_t symbols = 0;
    for (char c : payload) {
        if (c == '=' || !(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/')) break;
        ++symbols;
    }
    const std::uint64_t tail = symbols % 4;
    return symbols / 4 * 3 + (tail > 0 ? tail - 1 : 0);
}

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// The decoded size of a data URI tinygltf can decode, or the reason it cannot.
std::string checkDataUri(const std::string& uri, std::uint64_t maxBytes, std::uint64_t& decodedBytes) {
    // tinygltf decodes only base64 with a few media types; any other data URI it would try
    // to open as a file name.
    if (!tinygltf::IsDataURI(uri))
        return "data URI " + quoted(uri.substr(0, std::min<std::size_t>(uri.find(','), 60))) +
               " is not a base64 data URI with a supported media type";
    decodedBytes = base64DecodedSize(std::string_view(uri).substr(uri.find(',') + 1));
    if (decodedBytes > maxBytes)
        return "data URI holds " + std::to_string(decodedBytes) + " bytes, more than the limit of " +
               std::to_string(maxBytes);
    return {};
}

void checkBuffer(const LoadContext& context, const nlohmann::json& buffer, std::size_t index,
                 const GltfContainer& container) {
    const std::string object = indexed("buffers", index);
    if (!buffer.is_object()) context.fail(object, "is not an object");
    const auto byteLength = buffer.find("byteLength");
    if (byteLength == buffer.end() || !byteLength->is_number_unsigned())
        context.fail(object, "byteLength is missing or not a non-negative integer");
    const std::uint64_t length = byteLength->get<std::uint64_t>();
    // A GLB buffer of byteLength 0 makes tinygltf 2.7.0 throw std::out_of_range.
    if (length == 0) context.fail(object, "byteLength is 0 (glTF requires at least 1)");
    if (length > context.options.maxFileBytes)
        context.fail(object, "byteLength " + std::to_string(length) + " is more than the limit of " +
                                 std::to_string(context.options.maxFileBytes));

    const auto uri = buffer.find("uri");
    if (isDatalessFallbackBuffer(buffer)) return;  // no bytes to check: see GltfCompressionPlaceholders.h
    if (uri == buffer.end()) {
        if (!container.binary) context.fail(object, "has no uri (only a GLB's first buffer may omit it)");
        if (index != 0) context.fail(object, "has no uri, but only buffers[0] may refer to the GLB BIN chunk");
        if (length > container.bin.size())
            context.fail(object, "byteLength " + std::to_string(length) + " is more than the GLB BIN chunk holds (" +
                                     std::to_string(container.bin.size()) + " bytes)");
        return;
    }
    if (!uri->is_string()) context.fail(object, "uri is not a string");
    const std::string text = uri->get<std::string>();
    if (isDataUri(text)) {
        std::uint64_t decodedBytes = 0;
        if (const std::string problem = checkDataUri(text, context.options.maxFileBytes, decodedBytes); !problem.empty())
            context.fail(object, problem);
        if (decodedBytes != length)
            context.fail(object, "data URI holds " + std::to_string(decodedBytes) + " bytes, byteLength says " +
                                     std::to_string(length));
        return;
    }
    if (const std::string problem = checkExternalUri(text, context.folder, context.options.maxFileBytes); !problem.empty())
        context.fail(object, problem);
}

void checkImage(const LoadContext& context, const nlohmann::json& image, std::size_t index) {
    const std::string object = indexed("images", index);
    if (!image.is_object()) context.fail(object, "is not an object");
    const auto uri = image.find("uri");
    if (uri == image.end()) return;  // from a bufferView: checked after tinygltf, see GltfImages
    if (!uri->is_string()) context.fail(object, "uri is not a string");
    const std::string text = uri->get<std::string>();
    std::uint64_t decodedBytes = 0;
    const std::string problem = isDataUri(text) ? checkDataUri(text, context.options.maxFileBytes, decodedBytes)
                                                : checkExternalUri(text, context.folder, context.options.maxFileBytes);
    if (!problem.empty()) context.fail(object, problem);
}

// tinygltf 2.7.0 checks byteStride itself but without saying which view: check it first.
void checkBufferViewStride(const LoadContext& context, const nlohmann::json& view, std::size_t index) {
    if (!view.is_object()) return;
    const auto stride = view.find("byteStride");
    if (stride == view.end() || !stride->is_number_unsigned()) return;
    if (const std::string problem = byteStrideProblem(stride->get<std::uint64_t>()); !problem.empty())
        context.fail(indexed("bufferViews", index), problem);
}

// Applies `check` to every element of document[key] when it is an array (tinygltf reports
// other shapes itself).
template <typename Check>
void forEachIn(const nlohmann::json& document, const char* key, Check check) {
    const auto list = document.find(key);
    if (list == document.end() || !list->is_array()) return;
    for (std::size_t i = 0; i < list->size(); ++i) check((*list)[i], i);
}

} // namespace

bool isSupportedExtension(const std::string& name) {
    for (const char* supported : kSupportedExtensions)
        if (name == supported) return true;
    return false;
}

void preflightDocument(const LoadContext& context, const nlohmann::json& document,
                       const GltfContainer& container) {
    checkAssetVersion(context, document);
    checkExtensions(context, document);
    checkPropertyTypes(context, document);
    forEachIn(document, "buffers", [&](const nlohmann::json& buffer, std::size_t i) {
        checkBuffer(context, buffer, i, container);
    });
    forEachIn(document, "bufferViews", [&](const nlohmann::json& view, std::size_t i) {
        checkBufferViewStride(context, view, i);
    });
    forEachIn(document, "images", [&](const nlohmann::json& image, std::size_t i) {
        checkImage(context, image, i);
    });
}

} // namespace engine::gltf
