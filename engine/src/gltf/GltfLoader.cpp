// loadGltf: the order of the stages is the safety argument. Nothing reaches tinygltf
// before the container layout, the JSON nesting depth, every URI and every buffer length
// have been checked; nothing reads buffer bytes before the structural validation. The
// decoders of compressed data (meshopt views, Draco primitives) sit in between: each checks
// what it reads, and what they produce goes through the whole validation like any file.
#include "engine/gltf/GltfLoader.h"

#include "GltfContainer.h"
#include "GltfContext.h"
#include "GltfConvert.h"
#include "GltfDracoDecoder.h"
#include "GltfFileAccess.h"
#include "GltfJsonDocument.h"
#include "GltfLights.h"
#include "GltfMeshoptDecoder.h"
#include "GltfCompressionPlaceholders.h"
#include "GltfParse.h"
#include "GltfPreflight.h"
#include "GltfValidation.h"

#include "engine/render/Frame.h"
#include "engine/scene/SceneNames.h"

namespace engine {

namespace {

gltf::LoadContext makeContext(const std::filesystem::path& path, std::vector<std::string>* warnings,
                              const GltfLoadOptions& options) {
    gltf::LoadContext context;
    context.file = path.string();
    context.options = options;
    context.warnings = warnings;
    std::error_code error;
    const std::filesystem::path parent = path.parent_path().empty() ? "." : path.parent_path();
    context.folder = std::filesystem::canonical(parent, error);
    if (error) context.fail("", "cannot resolve the scene's folder: " + error.message());
    return context;
}

// tinygltf refuses parts of compressed files that the extensions allow: it parses a copy
// of the file with placeholders there (GltfCompressionPlaceholders.h).
gltf::ParsedGltf parseWithCompressionPlaceholders(const gltf::LoadContext& context, const nlohmann::json& document,
                                              const gltf::GltfContainer& container,
                                              std::span<const std::uint8_t> fileBytes) {
    const std::vector<std::uint8_t> rewritten = gltf::withCompressionPlaceholders(document, container);
    if (rewritten.empty()) return gltf::parseWithTinygltf(context, container, fileBytes);
    const gltf::GltfContainer rewrittenContainer =
        container.binary ? gltf::splitGlb(context, rewritten) : gltf::wholeFileAsJson(rewritten);
    return gltf::parseWithTinygltf(context, rewrittenContainer, rewritten);
}

} // namespace

Scene loadGltf(const std::filesystem::path& path, std::vector<std::string>* warnings,
               const GltfLoadOptions& options) {
    const gltf::LoadContext context = makeContext(path, warnings, options);

    std::vector<std::uint8_t> fileBytes;
    std::string problem;
    if (!gltf::readRegularFile(path, options.maxFileBytes, fileBytes, problem)) context.fail("", problem);

    const bool looksBinary = gltf::hasGlbMagic(fileBytes) || path.extension() == ".glb";
    const gltf::GltfContainer container = looksBinary ? gltf::splitGlb(context, fileBytes)
                                                      : gltf::wholeFileAsJson(fileBytes);
    gltf::checkJsonNesting(context, container.json);
    const nlohmann::json document = gltf::parseJsonDocument(context, container.json);
    gltf::preflightDocument(context, document, container);

    // Lights come from our own parse; tinygltf 2.7.0 parses them too but checks nothing.
    std::vector<Light> lights = gltf::readPunctualLights(context, document);
    gltf::ParsedGltf parsed = parseWithCompressionPlaceholders(context, document, container, fileBytes);
    gltf::decodeMeshoptBufferViews(context, document, parsed.model);
    gltf::validateBufferViews(context, parsed.model);
    gltf::validateReferences(context, parsed.model, lights.size());
    gltf::decodeDracoPrimitives(context, document, parsed.model);
    gltf::validateModel(context, parsed.model, lights.size());
    Scene scene = gltf::convertToScene(context, parsed, document, std::move(lights));
    if (const std::string dropped = lightsPastTheLimit(scene, kMaxClusteredLights); !dropped.empty())
        context.warn("", dropped);
    return scene;
}

} // namespace engine
