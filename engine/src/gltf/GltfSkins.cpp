#include "GltfSkins.h"

#include "GltfAccessors.h"
#include "GltfMeshes.h"

#include <set>
#include <string>

namespace engine::gltf {

std::vector<Skin> readSkins(const LoadContext& context, const tinygltf::Model& model) {
    std::vector<Skin> skins;
    skins.reserve(model.skins.size());
    for (std::size_t k = 0; k < model.skins.size(); ++k) {
        const tinygltf::Skin& source = model.skins[k];
        const std::string object = indexedNamed("skins", k, source.name);
        Skin skin;
        skin.name = source.name;
        if (source.joints.empty()) context.fail(object, "has no joints");
        std::set<int> seen;
        for (const int joint : source.joints)
            if (!seen.insert(joint).second) context.fail(object, "lists node " + std::to_string(joint) + " twice among its joints");
        skin.joints = source.joints;
        if (source.inverseBindMatrices < 0) {
            skin.inverseBindMatrices.assign(skin.joints.size(), glm::dmat4(1.0));
        } else {
            const AccessorUse use{"inverseBindMatrices of " + object, TINYGLTF_TYPE_MAT4, AccessorUse::Components::Float};
            const std::vector<float> values = readFloatComponents(context, model, source.inverseBindMatrices, use);
            if (values.size() != 16 * skin.joints.size())
                context.fail(object, "inverseBindMatrices holds " + std::to_string(values.size() / 16) + " matrices for " +
                                         std::to_string(skin.joints.size()) + " joints");
            for (std::size_t j = 0; j < skin.joints.size(); ++j) {
                glm::dmat4 matrix;
                for (int column = 0; column < 4; ++column)
                    for (int row = 0; row < 4; ++row) matrix[column][row] = values[16 * j + 4 * column + row];
                skin.inverseBindMatrices.push_back(matrix);
            }
        }
        skins.push_back(std::move(skin));
    }
    return skins;
}

namespace {

// Whether every primitive of the mesh carries skinning attributes; fails on a joint index
// past the skin's joints.
bool meshFitsSkin(const LoadContext& context, const Mesh& mesh, const Skin& skin, const std::string& object,
                  const std::string& skinName) {
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const Primitive& primitive = mesh.primitives[p];
        if (primitive.joints.empty()) return false;
        for (std::size_t v = 0; v < primitive.joints.size(); ++v)
            for (int i = 0; i < 4; ++i)
                if (primitive.joints[v][i] >= skin.joints.size() && primitive.weights[v][i] != 0.0f)
                    context.fail(object, "vertex " + std::to_string(v) + " of its mesh's primitive " + std::to_string(p) +
                                             " uses joint " + std::to_string(primitive.joints[v][i]) + " of " + skinName +
                                             ", which has " + std::to_string(skin.joints.size()) + " joints");
    }
    return true;
}

} // namespace

void attachDeformers(const LoadContext& context, const tinygltf::Model& model, const std::vector<Skin>& skins,
                     const std::vector<Mesh>& meshes, std::vector<Node>& nodes) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& source = model.nodes[i];
        const std::string object = indexedNamed("nodes", i, source.name);
        Node& node = nodes[i];
        if (source.skin >= 0) {
            const std::string skinName = indexedNamed("skins", source.skin, model.skins[source.skin].name);
            if (node.mesh < 0) {
                context.warn(object, "has " + skinName + " but no mesh; the skin is ignored");
            } else if (!meshFitsSkin(context, meshes[node.mesh], skins[source.skin], object, skinName)) {
                context.warn(object, "has " + skinName + " but its mesh has primitives without JOINTS_0/WEIGHTS_0; "
                                     "the skin is ignored");
            } else {
                node.skin = source.skin;
            }
        }
        if (source.weights.empty()) continue;
        const std::size_t targets =
            node.mesh >= 0 && !meshes[node.mesh].primitives.empty() ? meshes[node.mesh].primitives.front().targets.size() : 0;
        node.weights = checkedMorphWeights(context, object, source.weights, targets, "morph targets of its mesh");
    }
}

} // namespace engine::gltf
