#include "engine/scene/Deform.h"

#include "engine/scene/Scene.h"

#include <algorithm>
#include <cassert>

namespace engine {

namespace {

// The morph weights in effect: the node's, else the mesh's defaults.
const std::vector<float>& morphWeights(const Node& node, const Mesh& mesh) {
    return node.weights.empty() ? mesh.weights : node.weights;
}

struct JointMatrix {
    glm::dmat4 position;  // world(joint) * inverseBindMatrix
    glm::dmat3 normal;    // its inverse transpose
};

std::vector<JointMatrix> jointMatrices(const Scene& scene, const Skin& skin) {
    std::vector<JointMatrix> matrices;
    matrices.reserve(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const glm::dmat4 m = scene.nodes[skin.joints[j]].world * skin.inverseBindMatrices[j];
        matrices.push_back({m, glm::transpose(glm::inverse(glm::dmat3(m)))});
    }
    return matrices;
}

} // namespace

bool isDeformed(const Scene& scene, const Node& node) {
    if (node.mesh < 0) return false;
    if (node.skin >= 0) return true;
    const Mesh& mesh = scene.meshes[node.mesh];
    return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                       [](const Primitive& primitive) { return !primitive.targets.empty(); });
}

DeformedMesh deformMesh(const Scene& scene, const Node& node) {
    assert(node.mesh >= 0);
    const Mesh& mesh = scene.meshes[node.mesh];
    const std::vector<float>& weights = morphWeights(node, mesh);
    const Skin* skin = node.skin >= 0 ? &scene.skins[node.skin] : nullptr;
    const std::vector<JointMatrix> joints = skin ? jointMatrices(scene, *skin) : std::vector<JointMatrix>{};

    // Posed in double first; the origin (the posed bounds' centre) is known only after.
    std::vector<std::vector<glm::dvec3>> positions(mesh.primitives.size());
    DeformedMesh deformed;
    deformed.primitives.resize(mesh.primitives.size());
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const Primitive& source = mesh.primitives[p];
        const bool skinned = skin && !source.joints.empty();
        std::vector<glm::dvec3>& posed = positions[p];
        std::vector<glm::vec3>& normals = deformed.primitives[p].normals;
        posed.resize(source.positions.size());
        normals.resize(source.positions.size());
        for (std::size_t v = 0; v < source.positions.size(); ++v) {
            glm::dvec3 position(source.positions[v]);
            glm::dvec3 normal(source.normals[v]);
            for (std::size_t k = 0; k < source.targets.size() && k < weights.size(); ++k) {
                const MorphTarget& target = source.targets[k];
                position += double(weights[k]) * glm::dvec3(target.positions[v]);
                if (!target.normals.empty()) normal += double(weights[k]) * glm::dvec3(target.normals[v]);
            }
            if (skinned) {
                glm::dvec3 skinnedPosition(0.0), skinnedNormal(0.0);
                for (int i = 0; i < 4; ++i) {
                    const double w = source.weights[v][i];
                    if (w == 0.0) continue;
                    const JointMatrix& joint = joints[source.joints[v][i]];
                    skinnedPosition += w * glm::dvec3(joint.position * glm::dvec4(position, 1.0));
                    skinnedNormal += w * (joint.normal * normal);
                }
                position = skinnedPosition;
                normal = skinnedNormal;
            }
            posed[v] = position;
            const double length = glm::length(normal);
            normals[v] = length > 0.0 ? glm::vec3(normal / length) : glm::vec3(source.normals[v]);
            deformed.bounds.extend(position);
        }
    }
    deformed.origin = deformed.bounds.empty() ? glm::dvec3(0.0) : deformed.bounds.center();
    for (std::size_t p = 0; p < positions.size(); ++p) {
        std::vector<glm::vec3>& relative = deformed.primitives[p].positions;
        relative.reserve(positions[p].size());
        for (const glm::dvec3& position : positions[p]) relative.emplace_back(position - deformed.origin);
    }
    return deformed;
}

} // namespace engine
