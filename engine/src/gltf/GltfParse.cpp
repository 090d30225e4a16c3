#include "GltfParse.h"

#include "GltfFileAccess.h"

#include <limits>
#include <sstream>

namespace engine::gltf {

namespace {

// tinygltf calls this for every image. For a bufferView image the pointer it passes was
// computed from an unchecked offset, so it is not touched; for a URI image the bytes came
// through our sandboxed reader or a size-checked data URI and are kept as they are.
bool keepEncodedImageBytes(tinygltf::Image* image, const int imageIndex, std::string*, std::string*,
                           int, int, const unsigned char* bytes, int size, void* userData) {
    if (image->bufferView >= 0) return true;
    auto& kept = *static_cast<std::vector<std::vector<std::uint8_t>>*>(userData);
    if (imageIndex < 0) return false;
    if (kept.size() <= static_cast<std::size_t>(imageIndex)) kept.resize(imageIndex + 1);
    if (size > 0) kept[imageIndex].assign(bytes, bytes + size);
    return true;
}

// tinygltf's messages are newline-separated sentences; ours are one line.
std::string oneLine(const std::string& text) {
    std::istringstream lines(text);
    std::string line, joined;
    while (std::getline(lines, line)) {
        if (line.empty()) continue;
        joined += (joined.empty() ? "" : "; ") + line;
    }
    return joined;
}

// tinygltf 2.7.0 reports a skin without inverseBindMatrices as an error, but the glTF 2.0
// specification makes the property optional (each matrix is then the identity; readSkins
// fills them in). It still parses such a skin (inverseBindMatrices -1), so that one sentence
// is dropped from the error; any other message stands.
std::string withoutOptionalPropertyErrors(const std::string& error) {
    static const std::string kMissingInverseBind = "'inverseBindMatrices' property is missing in Skin.";
    std::istringstream lines(error);
    std::string line, kept;
    while (std::getline(lines, line))
        if (line != kMissingInverseBind) kept += line + '\n';
    return kept.find_first_not_of(" \n") == std::string::npos ? std::string() : kept;
}

void passWarningsOn(const LoadContext& context, const std::string& warnings) {
    std::istringstream lines(warnings);
    std::string line;
    while (std::getline(lines, line))
        if (!line.empty()) context.warn("tinygltf", line);
}

} // namespace

ParsedGltf parseWithTinygltf(const LoadContext& context, const GltfContainer& container,
                             std::span<const std::uint8_t> fileBytes) {
    // tinygltf takes lengths as unsigned int.
    if (fileBytes.size() > std::numeric_limits<unsigned int>::max())
        context.fail("", "the file is 4 GiB or larger");

    ParsedGltf parsed;
    SceneFolderSandbox sandbox{context.folder, context.options.maxFileBytes};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(makeSandboxedFsCallbacks(sandbox));
    loader.SetImageLoader(&keepEncodedImageBytes, &parsed.uriImageBytes);

    std::string error, warnings;
    bool loaded = false;
    const std::string baseDir = context.folder.string();
    try {
        if (container.binary)
            loaded = loader.LoadBinaryFromMemory(&parsed.model, &error, &warnings, fileBytes.data(),
                                                 static_cast<unsigned int>(fileBytes.size()), baseDir);
        else
            loaded = loader.LoadASCIIFromString(&parsed.model, &error, &warnings, container.json.data(),
                                                static_cast<unsigned int>(container.json.size()), baseDir);
    } catch (const std::exception& exception) {
        // 2.7.0 throws std::out_of_range on some malformed input (e.g. empty GLB buffers).
        context.fail("tinygltf", std::string("failed: ") + exception.what());
    }
    passWarningsOn(context, warnings);
    error = withoutOptionalPropertyErrors(error);
    // tinygltf can return true with an error string (e.g. a misaligned GLB JSON chunk).
    if (!loaded || !error.empty())
        context.fail("tinygltf", error.empty() ? "failed without a message" : oneLine(error));
    parsed.uriImageBytes.resize(parsed.model.images.size());
    return parsed;
}

} // namespace engine::gltf
