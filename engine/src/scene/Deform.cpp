#include "engine/scene/Deform.h"

#include "engine/scene/Scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace engine {

namespace {

// The morph weights in effect: the node's, else the mesh's defaults.
const std::vector<float>& morphWeights(const Node& node, const Mesh& mesh) {
    return node.weights.empty() ? mesh.weights : node.weights;
}

struct JointMatrix {
    glm::dmat4 position;   // world(joint) * inverseBindMatrix
    glm::dmat3 normal;     // its inverse transpose
    glm::dmat3 direction;  // its upper 3x3: directions along the surface (tangents)
};

std::vector<JointMatrix> jointMatrices(const Scene& scene, const Skin& skin) {
    std::vector<JointMatrix> matrices;
    matrices.reserve(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const glm::dmat4 m = scene.nodes[skin.joints[j]].world * skin.inverseBindMatrices[j];
        const glm::dmat3 direction(m);
        matrices.push_back({m, glm::transpose(glm::inverse(direction)), direction});
    }
    return matrices;
}

// One vertex on its way through the pose, in double. `tangent` is xyz only (w never
// changes) and unused when the primitive has no tangents.
struct PosedVertex {
    glm::dvec3 position;
    glm::dvec3 normal;
    glm::dvec3 tangent;
};

// Morph: base + sum_k w_k * delta_k for every attribute the targets move.
PosedVertex morphed(const Primitive& source, std::size_t v, const std::vector<float>& weights, bool withTangent) {
    PosedVertex vertex{glm::dvec3(source.positions[v]), glm::dvec3(source.normals[v]),
                       withTangent ? glm::dvec3(source.tangents[v]) : glm::dvec3(0.0)};
    for (std::size_t k = 0; k < source.targets.size() && k < weights.size(); ++k) {
        const MorphTarget& target = source.targets[k];
        const double weight = weights[k];
        vertex.position += weight * glm::dvec3(target.positions[v]);
        if (!target.normals.empty()) vertex.normal += weight * glm::dvec3(target.normals[v]);
        if (withTangent && !target.tangents.empty()) vertex.tangent += weight * glm::dvec3(target.tangents[v]);
    }
    return vertex;
}

// Skin: positions by sum_i w_i * J_i, normals by the inverse transposes. Tangents lie in
// the surface, so they move as differences of positions do, by the J_i's upper 3x3 (under
// a non-uniform scale, the inverse transpose would tilt them out of the surface).
PosedVertex skinned(const PosedVertex& vertex, const Primitive& source, std::size_t v,
                    const std::vector<JointMatrix>& joints) {
    PosedVertex result{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    for (int i = 0; i < 4; ++i) {
        const double w = source.weights[v][i];
        if (w == 0.0) continue;
        const JointMatrix& joint = joints[source.joints[v][i]];
        result.position += w * glm::dvec3(joint.position * glm::dvec4(vertex.position, 1.0));
        result.normal += w * (joint.normal * vertex.normal);
        result.tangent += w * (joint.direction * vertex.tangent);
    }
    return result;
}

// `v` at unit length, or `fallback` (the direction as loaded) when the pose cancelled it
// (or blew it beyond double range: absurd weights or joints must not leave NaN behind).
glm::vec3 unitOr(const glm::dvec3& v, const glm::vec3& fallback) {
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? glm::vec3(v / length) : fallback;
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
        const bool isSkinned = skin && !source.joints.empty();
        const bool withTangents = !source.tangents.empty();
        DeformedPrimitive& out = deformed.primitives[p];
        positions[p].resize(source.positions.size());
        out.normals.resize(source.positions.size());
        if (withTangents) out.tangents.resize(source.positions.size());
        for (std::size_t v = 0; v < source.positions.size(); ++v) {
            PosedVertex vertex = morphed(source, v, weights, withTangents);
            if (isSkinned) vertex = skinned(vertex, source, v, joints);
            positions[p][v] = vertex.position;
            out.normals[v] = unitOr(vertex.normal, source.normals[v]);
            if (withTangents)
                out.tangents[v] = glm::vec4(unitOr(vertex.tangent, glm::vec3(source.tangents[v])), source.tangents[v].w);
            deformed.bounds.extend(vertex.position);
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
