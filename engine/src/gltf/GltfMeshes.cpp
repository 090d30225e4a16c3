#include "GltfMeshes.h"

#include "GltfAccessors.h"
#include "GltfLightsShadows.h"

#include "engine/scene/Tangents.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

namespace engine::gltf {

namespace {

const char* modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    default: return "triangles";
    }
}

// The accessor index of `semantic`, if the primitive has that attribute.
std::optional<int> attribute(const tinygltf::Primitive& primitive, const char* semantic) {
    const auto found = primitive.attributes.find(semantic);
    if (found == primitive.attributes.end()) return std::nullopt;
    return found->second;
}

// The UV set TEXCOORD_<texCoord> of the primitive (empty when it has none).
const std::vector<glm::vec2>& uvSet(const Primitive& primitive, int texCoord) {
    return texCoord == 0 ? primitive.texcoords : primitive.texcoords1;
}

// A material's textures with their names in glTF, for messages.
struct NamedTexture {
    const char* name;
    const TextureRef* texture;
};
std::array<NamedTexture, 5> namedTextures(const Material& material) {
    return {{{"baseColorTexture", &material.baseColorTexture},
             {"metallicRoughnessTexture", &material.metallicRoughnessTexture},
             {"normalTexture", &material.normalTexture},
             {"occlusionTexture", &material.occlusionTexture},
             {"emissiveTexture", &material.emissiveTexture}}};
}

class PrimitiveConverter {
public:
    PrimitiveConverter(const LoadContext& context, const tinygltf::Model& model, const std::vector<Material>& materials,
                       const std::string& object)
        : context_(context), model_(model), materials_(materials), object_(object) {}

    // The engine primitive, or nothing when the primitive is not drawn as triangles. `json`
    // is the primitive as written (for its extensions).
    std::optional<Primitive> convert(const tinygltf::Primitive& source, const nlohmann::json& json) {
        const int mode = source.mode == -1 ? TINYGLTF_MODE_TRIANGLES : source.mode;
        if (mode < TINYGLTF_MODE_TRIANGLES) {
            context_.warn(object_, std::string(modeName(mode)) + " primitive dropped (only triangles are drawn)");
            return std::nullopt;
        }
        const std::optional<int> positionAccessor = attribute(source, "POSITION");
        if (!positionAccessor) {
            context_.warn(object_, "primitive without POSITION dropped");
            return std::nullopt;
        }

        Primitive primitive;
        primitive.material = source.material;
        primitive.positions = readFloatVectors<3>(
            context_, model_, *positionAccessor, vectorUse("POSITION", TINYGLTF_TYPE_VEC3, AccessorUse::Components::Quantized));
        const std::size_t vertexCount = primitive.positions.size();
        if (vertexCount > std::numeric_limits<std::uint32_t>::max())
            context_.fail(object_, "has more vertices than 32-bit indices can address");
        if (const auto normals = attribute(source, "NORMAL")) {
            primitive.normals = readFloatVectors<3>(
                context_, model_, *normals,
                vectorUse("NORMAL", TINYGLTF_TYPE_VEC3, AccessorUse::Components::FloatOrSignedNormalized));
            requireVertexCount("NORMAL", primitive.normals.size(), vertexCount);
        }
        primitive.texcoords = readTexcoords(source, "TEXCOORD_0", vertexCount);
        primitive.texcoords1 = readTexcoords(source, "TEXCOORD_1", vertexCount);
        primitive.colors = readColors(source, vertexCount);
        primitive.tangents = readTangents(source, vertexCount);
        readSkinWeights(source, vertexCount, primitive);
        primitive.targets = readMorphTargets(source, vertexCount);
        dropTangentOffsetsWithoutTangents(primitive);
        const ShadowFlags shadows = readLightsShadows(JsonFields(context_, object_, json, ""), ShadowFlagsOwner::Primitive);
        primitive.castShadows = shadows.castShadows;
        primitive.receiveShadows = shadows.receiveShadows;
        warnAboutMissingUvSets(primitive);

        const std::vector<std::uint32_t> vertexIndices = readVertexIndices(source, vertexCount);
        if (mode == TINYGLTF_MODE_TRIANGLES && vertexIndices.size() % 3 != 0)
            context_.fail(object_, std::to_string(vertexIndices.size()) +
                                       " vertices do not make whole triangles (not a multiple of 3)");
        primitive.indices = triangleList(mode, vertexIndices);

        if (primitive.normals.empty()) {
            primitive.normals = generateNormals(primitive.positions, primitive.indices);
            context_.warn(object_, "has no NORMAL; normals generated");
        }
        completeTangents(primitive);
        for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(glm::dvec3(p));
        return primitive;
    }

private:
    // Positions, normals and texture coordinates take the KHR_mesh_quantization types too;
    // they are read whether or not the file declares the extension, as the values mean
    // the same either way.
    AccessorUse vectorUse(const char* semantic, int type, AccessorUse::Components components) const {
        return {std::string(semantic) + " of " + object_, type, components};
    }

    // TEXCOORD_n: FLOAT or normalized unsigned, one per vertex; empty when absent.
    std::vector<glm::vec2> readTexcoords(const tinygltf::Primitive& source, const char* semantic,
                                         std::size_t vertexCount) const {
        const std::optional<int> accessor = attribute(source, semantic);
        if (!accessor) return {};
        const AccessorUse use = vectorUse(semantic, TINYGLTF_TYPE_VEC2, AccessorUse::Components::Quantized);
        std::vector<glm::vec2> texcoords = readFloatVectors<2>(context_, model_, *accessor, use);
        requireVertexCount(semantic, texcoords.size(), vertexCount);
        return texcoords;
    }

    // COLOR_0 as RGBA: VEC3 or VEC4 of FLOAT or normalized unsigned; VEC3 is opaque.
    std::vector<glm::vec4> readColors(const tinygltf::Primitive& source, std::size_t vertexCount) const {
        const std::optional<int> accessor = attribute(source, "COLOR_0");
        if (!accessor) return {};
        AccessorUse use = vectorUse("COLOR_0", TINYGLTF_TYPE_VEC3, AccessorUse::Components::FloatOrNormalized);
        use.alternativeType = TINYGLTF_TYPE_VEC4;
        std::vector<glm::vec4> colors;
        if (model_.accessors[*accessor].type == TINYGLTF_TYPE_VEC3) {
            for (const glm::vec3& rgb : readFloatVectors<3>(context_, model_, *accessor, use))
                colors.emplace_back(rgb, 1.0f);
        } else {
            colors = readFloatVectors<4>(context_, model_, *accessor, use);  // refuses any other type
        }
        requireVertexCount("COLOR_0", colors.size(), vertexCount);
        return colors;
    }

    // TANGENT: VEC4 of FLOAT or normalized BYTE/SHORT (KHR_mesh_quantization, as NORMAL);
    // empty when absent. Non-finite values are refused by the accessor reader; xyz is made
    // unit by completeTangents, once the normals a zero tangent is replaced from are known.
    std::vector<glm::vec4> readTangents(const tinygltf::Primitive& source, std::size_t vertexCount) const {
        const std::optional<int> accessor = attribute(source, "TANGENT");
        if (!accessor) return {};
        std::vector<glm::vec4> tangents = readFloatVectors<4>(
            context_, model_, *accessor,
            vectorUse("TANGENT", TINYGLTF_TYPE_VEC4, AccessorUse::Components::FloatOrSignedNormalized));
        requireVertexCount("TANGENT", tangents.size(), vertexCount);
        for (std::size_t v = 0; v < tangents.size(); ++v) tangents[v].w = handedness(tangents[v].w, v);
        return tangents;
    }

    // glTF: TANGENT's w "is a sign value (-1 or +1)". Normalized BYTE and SHORT encode +-1
    // exactly (127/127 = 1; -127 and -128 both decode to -1), so the 1e-3 tolerance is only
    // for float exporters that round (0.99999994). Stored exactly, as shaders multiply by it.
    float handedness(float w, std::size_t vertex) const {
        if (!(std::fabs(std::fabs(w) - 1.0f) <= 1e-3f))
            context_.fail(object_, "TANGENT of vertex " + std::to_string(vertex) + " has w " + formatNumber(w) +
                                       ", not +1 or -1 (the bitangent's sign)");
        return w < 0.0f ? -1.0f : 1.0f;
    }

    // Once the normals are final: the file's tangents made unit, or tangents generated for a
    // material with a normal texture (when the primitive has its UV set), or none. Generated
    // from the UVs the normal texture is sampled at, its KHR_texture_transform applied: a
    // rotated or mirrored mapping turns the map's x and y with it.
    void completeTangents(Primitive& primitive) const {
        if (!primitive.tangents.empty()) {
            normalizeTangents(primitive);
            return;
        }
        if (primitive.material < 0) return;
        const TextureRef& normalTexture = materials_[primitive.material].normalTexture;
        if (!normalTexture.present()) return;
        std::vector<glm::vec2> uvs = uvSet(primitive, normalTexture.texCoord);
        if (uvs.empty()) return;  // reported by warnAboutMissingUvSets
        for (glm::vec2& uv : uvs) uv = normalTexture.transform.apply(uv);
        primitive.tangents = generateTangents(primitive.positions, primitive.normals, uvs, primitive.indices);
    }

    // The file's tangents to unit length. A zero one has no direction to keep: it becomes a
    // direction perpendicular to the vertex normal (its w kept), reported once per primitive
    // (an exporter that writes one zero tangent usually writes many).
    void normalizeTangents(Primitive& primitive) const {
        std::size_t zeros = 0, firstZero = 0;
        for (std::size_t v = 0; v < primitive.tangents.size(); ++v) {
            glm::vec4& tangent = primitive.tangents[v];
            const glm::dvec3 xyz(tangent);
            const double length = glm::length(xyz);
            if (length > 0.0) {
                tangent = glm::vec4(glm::vec3(xyz / length), tangent.w);
                continue;
            }
            if (zeros++ == 0) firstZero = v;
            tangent = glm::vec4(anyPerpendicular(primitive.normals[v]), tangent.w);
        }
        if (zeros > 0)
            context_.warn(object_, "TANGENT of " + std::to_string(zeros) + " vertices (the first: vertex " +
                                       std::to_string(firstZero) +
                                       ") has zero length; replaced by a direction perpendicular to the normal");
    }

    // JOINTS_0 (unsigned byte or short) and WEIGHTS_0 (float or normalized unsigned), both
    // or neither. Each vertex's weights are normalized to sum to 1 (glTF requires the sum to
    // be 1 within the quantization's precision; exporters round); a vertex whose weights sum
    // to 0 has no pose and is refused. Whether a joint index exists is checked per skin
    // (GltfSkins.cpp): the mesh does not know which skin poses it.
    void readSkinWeights(const tinygltf::Primitive& source, std::size_t vertexCount, Primitive& primitive) const {
        const std::optional<int> joints = attribute(source, "JOINTS_0");
        const std::optional<int> weights = attribute(source, "WEIGHTS_0");
        if (!joints && !weights) return;
        if (!joints || !weights)
            context_.fail(object_, std::string("has ") + (joints ? "JOINTS_0 without WEIGHTS_0" : "WEIGHTS_0 without JOINTS_0"));
        if (attribute(source, "JOINTS_1"))
            context_.warn(object_, "JOINTS_1/WEIGHTS_1 ignored: four joints per vertex are used");
        const std::vector<std::uint32_t> indices = readUnsignedIntegers(
            context_, model_, *joints, vectorUse("JOINTS_0", TINYGLTF_TYPE_VEC4, AccessorUse::Components::UnsignedInteger));
        requireVertexCount("JOINTS_0", indices.size() / 4, vertexCount);
        primitive.weights = readFloatVectors<4>(
            context_, model_, *weights, vectorUse("WEIGHTS_0", TINYGLTF_TYPE_VEC4, AccessorUse::Components::FloatOrNormalized));
        requireVertexCount("WEIGHTS_0", primitive.weights.size(), vertexCount);
        primitive.joints.resize(vertexCount);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            primitive.joints[v] = {indices[4 * v], indices[4 * v + 1], indices[4 * v + 2], indices[4 * v + 3]};
            glm::vec4& w = primitive.weights[v];
            const float sum = w.x + w.y + w.z + w.w;
            if (glm::any(glm::lessThan(w, glm::vec4(0.0f))) || !(sum > 0.0f))
                context_.fail(object_, "WEIGHTS_0 of vertex " + std::to_string(v) + " are (" + formatNumber(w.x) + ", " +
                                           formatNumber(w.y) + ", " + formatNumber(w.z) + ", " + formatNumber(w.w) +
                                           "): weights must be >= 0 and not all 0");
            w /= sum;
        }
    }

    // Morph targets: POSITION, NORMAL and TANGENT offsets per vertex (TANGENT's are xyz
    // only: a target does not change the handedness).
    std::vector<MorphTarget> readMorphTargets(const tinygltf::Primitive& source, std::size_t vertexCount) const {
        std::vector<MorphTarget> targets(source.targets.size());
        for (std::size_t t = 0; t < source.targets.size(); ++t) {
            const auto& attributes = source.targets[t];
            const std::string name = indexed("targets", t);
            targets[t].positions =
                readOffsets(attributes, name, "POSITION", AccessorUse::Components::Quantized, vertexCount);
            if (targets[t].positions.empty()) targets[t].positions.assign(vertexCount, glm::vec3(0.0f));
            targets[t].normals =
                readOffsets(attributes, name, "NORMAL", AccessorUse::Components::FloatOrSignedNormalized, vertexCount);
            targets[t].tangents =
                readOffsets(attributes, name, "TANGENT", AccessorUse::Components::FloatOrSignedNormalized, vertexCount);
        }
        return targets;
    }

    // The VEC3 offsets of `semantic` in morph target `target` (e.g. "targets[0]"), one per
    // vertex; empty when the target does not move that attribute.
    std::vector<glm::vec3> readOffsets(const std::map<std::string, int>& attributes, const std::string& target,
                                       const char* semantic, AccessorUse::Components components,
                                       std::size_t vertexCount) const {
        const auto found = attributes.find(semantic);
        if (found == attributes.end()) return {};
        const std::string usedAs = target + " " + semantic;
        std::vector<glm::vec3> offsets =
            readFloatVectors<3>(context_, model_, found->second, vectorUse(usedAs.c_str(), TINYGLTF_TYPE_VEC3, components));
        requireVertexCount(usedAs.c_str(), offsets.size(), vertexCount);
        return offsets;
    }

    // TANGENT offsets displace the file's TANGENT: without one there is nothing they were
    // authored against (generated tangents are not the file's), so they are dropped.
    void dropTangentOffsetsWithoutTangents(Primitive& primitive) const {
        if (!primitive.tangents.empty()) return;
        bool dropped = false;
        for (MorphTarget& target : primitive.targets) {
            dropped = dropped || !target.tangents.empty();
            target.tangents.clear();
        }
        if (dropped) context_.warn(object_, "morph target TANGENT offsets ignored: the primitive has no TANGENT");
    }

    // A material texture sampling a UV set the primitive lacks still draws, sampling every
    // vertex at uv (0,0): worth a warning, not a refusal (exporters drop unused sets). A
    // normal texture without its UV set has no tangent frame to be generated from: without
    // the file's TANGENT, the primitive is drawn without its normal map.
    void warnAboutMissingUvSets(const Primitive& primitive) const {
        if (primitive.material < 0) return;
        const Material& material = materials_[primitive.material];
        for (const auto& [name, texture] : namedTextures(material)) {
            if (!texture->present() || !uvSet(primitive, texture->texCoord).empty()) continue;
            const bool normalMapDropped = texture == &material.normalTexture && primitive.tangents.empty();
            const char* consequence = normalMapDropped
                                          ? "no tangents are generated and the normal map is ignored for this primitive"
                                          : "it is sampled at uv (0,0)";
            context_.warn(object_, "has no TEXCOORD_" + std::to_string(texture->texCoord) + ", which the " + name +
                                       " of " + indexedNamed("materials", primitive.material, material.name) +
                                       " samples; " + consequence);
        }
    }

    void requireVertexCount(const char* semantic, std::size_t count, std::size_t vertexCount) const {
        if (count != vertexCount)
            context_.fail(object_, std::string(semantic) + " has " + std::to_string(count) +
                                       " elements, POSITION has " + std::to_string(vertexCount));
    }

    // The primitive's indices, each checked against the vertex count; 0..n-1 when the
    // primitive is not indexed.
    std::vector<std::uint32_t> readVertexIndices(const tinygltf::Primitive& source, std::size_t vertexCount) const {
        if (source.indices < 0) {
            std::vector<std::uint32_t> sequential(vertexCount);
            std::iota(sequential.begin(), sequential.end(), 0u);
            return sequential;
        }
        const AccessorUse use{"indices of " + object_, TINYGLTF_TYPE_SCALAR, AccessorUse::Components::UnsignedInteger};
        std::vector<std::uint32_t> indices = readUnsignedIntegers(context_, model_, source.indices, use);
        for (std::size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= vertexCount)
                context_.fail(indexed("accessors", source.indices),
                              "used as " + use.usedAs + ", index " + std::to_string(indices[i]) + " (element " +
                                  std::to_string(i) + ") is past the vertex count " + std::to_string(vertexCount));
        return indices;
    }

    const LoadContext& context_;
    const tinygltf::Model& model_;
    const std::vector<Material>& materials_;
    std::string object_;
};

// Every primitive of a mesh has the same number of morph targets (glTF 2.0 section
// 3.7.2.2); the mesh's weights, when given, one per target (else zeros).
void readMorphWeights(const LoadContext& context, const tinygltf::Mesh& source, const std::string& object, Mesh& mesh) {
    const std::size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives.front().targets.size();
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        if (mesh.primitives[p].targets.size() != targets)
            context.fail(object, "its primitives have " + std::to_string(targets) + " and " +
                                     std::to_string(mesh.primitives[p].targets.size()) +
                                     " morph targets (glTF requires the same count in every primitive)");
    if (source.weights.empty()) {
        mesh.weights.assign(targets, 0.0f);
        return;
    }
    mesh.weights = checkedMorphWeights(context, object, source.weights, targets, "morph targets");
}

Mesh convertMesh(const LoadContext& context, const tinygltf::Model& model, const nlohmann::json& document,
                 const std::vector<Material>& materials, std::size_t meshIndex) {
    const tinygltf::Mesh& source = model.meshes[meshIndex];
    Mesh mesh;
    mesh.name = source.name;
    const std::string meshObject = indexedNamed("meshes", meshIndex, source.name);
    const nlohmann::json& meshJson = arrayElement(document, "meshes", meshIndex);
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
        PrimitiveConverter converter(context, model, materials, meshObject + "." + indexed("primitives", p));
        if (std::optional<Primitive> primitive =
                converter.convert(source.primitives[p], arrayElement(meshJson, "primitives", p))) {
            mesh.bounds.extend(primitive->bounds);
            mesh.primitives.push_back(std::move(*primitive));
        }
    }
    mesh.closed = isClosedSurface(mesh);
    readMorphWeights(context, source, meshObject, mesh);
    return mesh;
}

} // namespace

std::vector<float> checkedMorphWeights(const LoadContext& context, const std::string& object,
                                       const std::vector<double>& weights, std::size_t targets, const char* targetsName) {
    if (weights.size() != targets)
        context.fail(object, "weights has " + std::to_string(weights.size()) + " entries for " + std::to_string(targets) +
                                 " " + targetsName);
    std::vector<float> out;
    for (const double weight : weights) {
        if (!std::isfinite(weight)) context.fail(object, "weights holds " + formatNumber(weight) + ", not a finite number");
        out.push_back(static_cast<float>(weight));
    }
    return out;
}

std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& indices) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return indices;
    std::vector<std::uint32_t> triangles;
    if (indices.size() < 3) return triangles;
    triangles.reserve((indices.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // glTF: {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}: every other triangle swaps its last
            // two vertices so all keep the strip's winding.
            triangles.insert(triangles.end(), {indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]});
        } else {
            // glTF: {v_{i+1}, v_{i+2}, v_0}.
            triangles.insert(triangles.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
    }
    return triangles;
}

std::vector<Mesh> convertMeshes(const LoadContext& context, const tinygltf::Model& model,
                                const nlohmann::json& document, const std::vector<Material>& materials) {
    std::vector<Mesh> meshes;
    meshes.reserve(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        meshes.push_back(convertMesh(context, model, document, materials, m));
    return meshes;
}

} // namespace engine::gltf
