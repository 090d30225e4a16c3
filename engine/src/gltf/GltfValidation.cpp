// Binary layout and cross-references; the node graph is in GltfNodeGraphValidation.cpp.
#include "GltfValidation.h"

#include "GltfLights.h"

namespace engine::gltf {

namespace {

constexpr std::uint64_t kMaxByteStride = 252;  // glTF 2.0: byteStride in [4, 252], multiple of 4

// a*b + c in 64 bits, or false on overflow.
bool mulAdd(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t& result) {
    std::uint64_t product;
    return !__builtin_mul_overflow(a, b, &product) && !__builtin_add_overflow(product, c, &result);
}

std::string runsPast(const std::string& container, std::uint64_t needed, std::uint64_t has) {
    return "runs past the end of " + container + " (needs " + std::to_string(needed) + " bytes, has " +
           std::to_string(has) + ")";
}

void validateAccessor(const LoadContext& context, const tinygltf::Model& model, std::size_t index) {
    const tinygltf::Accessor& accessor = model.accessors[index];
    const std::string object = indexed("accessors", index);
    if (accessor.sparse.isSparse) context.fail(object, "sparse accessors are not supported");
    const std::uint64_t bytesPerComponent = componentSize(accessor.componentType);
    if (bytesPerComponent == 0)
        context.fail(object, "componentType " + std::to_string(accessor.componentType) +
                                 " is not a glTF 2.0 component type");
    const std::uint64_t components = componentsPerElement(accessor.type);
    if (components == 0) context.fail(object, "type " + std::to_string(accessor.type) + " is unknown");
    // Limits first: later stages allocate count elements.
    if (accessor.count > context.options.maxElementCount)
        context.fail(object, "count " + std::to_string(accessor.count) + " is more than the limit of " +
                                 std::to_string(context.options.maxElementCount));
    // count - 1 below must not wrap around.
    if (accessor.count == 0) context.fail(object, "count is 0 (glTF requires at least 1)");
    if (accessor.bufferView < 0) {
        // glTF allows an all-zero accessor without a view, but nothing in the file backs its
        // count: the fuzzer made a 154-byte file allocate 1.6 GB through one. Such accessors
        // only make sense with sparse data, which the engine does not support.
        context.fail(object, "has no bufferView (all-zero accessors are only used with sparse "
                             "accessors, which are not supported)");
    }
    if (static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
        context.fail(object, "bufferView " + std::to_string(accessor.bufferView) + " does not exist");

    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    const std::string viewName = indexed("bufferViews", accessor.bufferView);
    const std::uint64_t elementBytes = components * bytesPerComponent;
    if (view.byteStride != 0 && view.byteStride < elementBytes)
        context.fail(object, viewName + " byteStride " + std::to_string(view.byteStride) +
                                 " is smaller than the element size " + std::to_string(elementBytes));
    const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : elementBytes;
    // The last element starts at byteOffset + stride*(count-1) and is elementBytes long.
    std::uint64_t lastStart = 0, end = 0;
    if (!mulAdd(stride, accessor.count - 1, accessor.byteOffset, lastStart) ||
        __builtin_add_overflow(lastStart, elementBytes, &end))
        context.fail(object, "byteOffset " + std::to_string(accessor.byteOffset) + ", stride " +
                                 std::to_string(stride) + " and count " + std::to_string(accessor.count) +
                                 " overflow 64 bits");
    if (end > view.byteLength) context.fail(object, runsPast(viewName, end, view.byteLength));
}

void requireIndex(const LoadContext& context, const std::string& object, const char* what, int index,
                  std::size_t size, bool optional) {
    if (optional && index == -1) return;
    if (index < 0 || static_cast<std::size_t>(index) >= size)
        context.fail(object, std::string(what) + " " + std::to_string(index) + " does not exist (there are " +
                                 std::to_string(size) + ")");
}

void validateMeshReferences(const LoadContext& context, const tinygltf::Model& model) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const auto& primitives = model.meshes[m].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = primitives[p];
            const std::string object = indexed("meshes", m) + "." + indexed("primitives", p);
            for (const auto& [semantic, accessor] : primitive.attributes)
                requireIndex(context, object, ("attribute " + semantic + ": accessor").c_str(), accessor,
                             model.accessors.size(), false);
            requireIndex(context, object, "indices: accessor", primitive.indices, model.accessors.size(), true);
            for (std::size_t t = 0; t < primitive.targets.size(); ++t)
                for (const auto& [semantic, accessor] : primitive.targets[t])
                    requireIndex(context, object, (indexed("targets", t) + " " + semantic + ": accessor").c_str(),
                                 accessor, model.accessors.size(), false);
            requireIndex(context, object, "material", primitive.material, model.materials.size(), true);
            // -1: tinygltf's "absent", which means TRIANGLES.
            if (primitive.mode < -1 || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
                context.fail(object, "mode " + std::to_string(primitive.mode) + " is not a glTF primitive mode");
        }
    }
}

void validateMaterialReferences(const LoadContext& context, const tinygltf::Model& model) {
    // Every texture a material reads (GltfMaterials.cpp converts each of these).
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& material = model.materials[i];
        const std::pair<const char*, int> references[] = {
            {"baseColorTexture: texture", material.pbrMetallicRoughness.baseColorTexture.index},
            {"metallicRoughnessTexture: texture", material.pbrMetallicRoughness.metallicRoughnessTexture.index},
            {"normalTexture: texture", material.normalTexture.index},
            {"occlusionTexture: texture", material.occlusionTexture.index},
            {"emissiveTexture: texture", material.emissiveTexture.index},
        };
        for (const auto& [what, index] : references)
            requireIndex(context, indexed("materials", i), what, index, model.textures.size(), true);
    }
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        requireIndex(context, indexed("textures", i), "source: image", model.textures[i].source,
                     model.images.size(), true);
        requireIndex(context, indexed("textures", i), "sampler", model.textures[i].sampler,
                     model.samplers.size(), true);
    }
    for (std::size_t i = 0; i < model.images.size(); ++i)
        requireIndex(context, indexed("images", i), "bufferView", model.images[i].bufferView,
                     model.bufferViews.size(), true);
}

void validateNodeReferences(const LoadContext& context, const tinygltf::Model& model, std::size_t lightCount) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& node = model.nodes[i];
        const std::string object = indexedNamed("nodes", i, node.name);
        requireIndex(context, object, "mesh", node.mesh, model.meshes.size(), true);
        requireIndex(context, object, "camera", node.camera, model.cameras.size(), true);
        requireIndex(context, object, "skin", node.skin, model.skins.size(), true);
        requireIndex(context, object, "KHR_lights_punctual light", nodeLightIndex(context, node, i), lightCount, true);
        for (int child : node.children)
            requireIndex(context, object, "child node", child, model.nodes.size(), false);
    }
    for (std::size_t k = 0; k < model.skins.size(); ++k) {
        const std::string object = indexedNamed("skins", k, model.skins[k].name);
        for (int joint : model.skins[k].joints) requireIndex(context, object, "joint node", joint, model.nodes.size(), false);
        requireIndex(context, object, "inverseBindMatrices: accessor", model.skins[k].inverseBindMatrices,
                     model.accessors.size(), true);
    }
    for (std::size_t s = 0; s < model.scenes.size(); ++s)
        for (int root : model.scenes[s].nodes)
            requireIndex(context, indexed("scenes", s), "node", root, model.nodes.size(), false);
    if (model.defaultScene != -1)
        requireIndex(context, "scene", "scene", model.defaultScene, model.scenes.size(), false);
}

} // namespace

std::string byteStrideProblem(std::uint64_t byteStride) {
    if (byteStride == 0 || (byteStride >= 4 && byteStride <= kMaxByteStride && byteStride % 4 == 0)) return {};
    return "byteStride " + std::to_string(byteStride) + " is not a multiple of 4 in [4, 252]";
}

std::size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // INT and DOUBLE are not glTF 2.0 accessor types
    }
}

std::size_t componentsPerElement(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

void validateBufferViews(const LoadContext& context, const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const tinygltf::BufferView& view = model.bufferViews[i];
        const std::string object = indexed("bufferViews", i);
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
            context.fail(object, "buffer " + std::to_string(view.buffer) + " does not exist");
        if (view.byteLength == 0) context.fail(object, "byteLength is 0 (glTF requires at least 1)");
        const std::uint64_t bufferBytes = model.buffers[view.buffer].data.size();
        std::uint64_t end = 0;
        if (__builtin_add_overflow(std::uint64_t{view.byteOffset}, std::uint64_t{view.byteLength}, &end))
            context.fail(object, "byteOffset + byteLength overflows 64 bits");
        if (end > bufferBytes) context.fail(object, runsPast(indexed("buffers", view.buffer), end, bufferBytes));
        if (const std::string problem = byteStrideProblem(view.byteStride); !problem.empty())
            context.fail(object, problem);
    }
}

void validateBinaryLayout(const LoadContext& context, const tinygltf::Model& model) {
    validateBufferViews(context, model);
    for (std::size_t i = 0; i < model.accessors.size(); ++i) validateAccessor(context, model, i);
}

void validateReferences(const LoadContext& context, const tinygltf::Model& model, std::size_t lightCount) {
    validateMeshReferences(context, model);
    validateMaterialReferences(context, model);
    validateNodeReferences(context, model, lightCount);
}

void validateModel(const LoadContext& context, const tinygltf::Model& model, std::size_t lightCount) {
    validateBinaryLayout(context, model);
    validateReferences(context, model, lightCount);
    validateNodeGraph(context, model);
}

} // namespace engine::gltf
