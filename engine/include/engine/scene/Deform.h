#pragma once
// Skinning and morph targets, on the CPU: the one routine that poses a deformed instance's
// vertices for every pass that draws it (SceneGpu uploads the result once per change) and
// for the ray-traced truth (the same floats). Why the CPU: on Mesa llvmpipe vertex shading
// is CPU work that every pass drawing the mesh would repeat (the lit pass, each depth pass,
// six cube faces, woo's two passes); posing once costs about one of them, the bounds come
// exact from the posed vertices, and the passes and the truth see bit-identical vertices.
#include "engine/scene/Aabb.h"

#include <glm/glm.hpp>

#include <vector>

namespace engine {

struct Scene;
struct Node;

struct DeformedPrimitive {
    std::vector<glm::vec3> positions;  // relative to DeformedMesh::origin
    std::vector<glm::vec3> normals;    // unit length
    // Unit xyz posed with the surface (Primitive::tangents, w as loaded); empty when the
    // primitive has no tangents.
    std::vector<glm::vec4> tangents;
    bool operator==(const DeformedPrimitive&) const = default;
};

struct DeformedMesh {
    // The vertices' frame is world space for a skinned mesh (glTF ignores the skinned mesh
    // node's transform) and the node's object space for a morphed one. Positions are stored
    // relative to `origin` (subtracted in double, as SceneGpu does for meshes), so a posed
    // mesh far from the world origin keeps its float precision.
    glm::dvec3 origin{0.0};
    std::vector<DeformedPrimitive> primitives;  // one per Mesh::primitives entry
    Aabb bounds;  // of the posed vertices, in the frame (not relative to origin)
    bool operator==(const DeformedMesh&) const = default;
};

// Whether the node's mesh is drawn deformed: the node has a skin, or the mesh has morph
// targets.
bool isDeformed(const Scene& scene, const Node& node);

// The node's mesh posed by the joints' current world transforms and the node's morph
// weights (else the mesh's). Per vertex, in double: morph first (base + sum_k w_k * delta_k,
// positions, normals and tangents' xyz), then skin (positions by sum_i w_i * J_i with
// J = world(joint) * inverseBindMatrix, normals by the inverse transposes of the J_i,
// tangents by the J_i's upper 3x3: they are directions in the surface, as edges are);
// normals and tangents then normalized, tangents' w unchanged.
// Node world transforms must be current (Scene::updateWorldTransforms calls this).
DeformedMesh deformMesh(const Scene& scene, const Node& node);

} // namespace engine
