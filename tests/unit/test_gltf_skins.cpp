// Skins and morph targets: the loader reads them and refuses what cannot be posed; the CPU
// deformation (Deform.h) gives hand-computed vertices; the instance's bounds and revision
// follow the pose, not the mesh as loaded.
#include "engine/scene/Deform.h"
#include "engine/scene/Scene.h"
#include "gltf_test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>

namespace {

using namespace gltf_test;

// The instance's vertex v of primitive 0 as posed, in world space.
glm::dvec3 posedVertex(const engine::Scene& scene, std::size_t v) {
    const engine::MeshInstance& instance = scene.meshInstances.at(0);
    EXPECT_TRUE(instance.deformed);
    const glm::dvec3 object = instance.deformed->origin + glm::dvec3(instance.deformed->primitives.at(0).positions.at(v));
    return glm::dvec3(instance.world * glm::dvec4(object, 1.0));
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected) {
    // Positions are stored as floats relative to the pose's centre: 1e-6 is several float
    // steps at the magnitudes here (|x| < 4).
    EXPECT_NEAR(actual.x, expected.x, 1e-6);
    EXPECT_NEAR(actual.y, expected.y, 1e-6);
    EXPECT_NEAR(actual.z, expected.z, 1e-6);
}

TEST(GltfSkins, JointsPoseTheVerticesAndTheNodeTransformIsIgnored) {
    TempDir dir;
    engine::Scene scene = engine::loadGltf(skinnedQuad().writeGltf(dir.path(), "skinned"));
    ASSERT_EQ(scene.skins.size(), 1u);
    ASSERT_EQ(scene.nodes[0].skin, 0);
    // At rest every joint sits where it was bound: the quad as loaded, not moved by 100.
    expectNear(posedVertex(scene, 2), {1, 1, 0});
    const std::uint64_t restRevision = scene.meshInstances[0].revision;
    scene.updateWorldTransforms();
    EXPECT_EQ(scene.meshInstances[0].revision, restRevision) << "nothing moved";

    // Tip moves to (2, 1, 0): J_tip = T(2, 1, 0) * T(0, -1, 0) = T(2, 0, 0).
    engine::Node& tip = scene.nodes[2];
    tip.translation = {2, 1, 0};
    tip.local = tip.trsMatrix();
    scene.updateWorldTransforms();
    expectNear(posedVertex(scene, 0), {0, 0, 0});
    expectNear(posedVertex(scene, 1), {1, 0, 0});
    expectNear(posedVertex(scene, 2), {3, 1, 0});
    expectNear(posedVertex(scene, 3), {1, 1, 0});  // (0, 1, 0) half by I, half by T(2, 0, 0)
    EXPECT_NE(scene.meshInstances[0].revision, restRevision) << "the pose changed";
    // The bounds are the pose's: x from 0 to 3 (the mesh as loaded spans 0 to 1, and the
    // node's own transform would have put it at 100).
    const engine::Aabb& bounds = scene.meshInstances[0].worldBounds;
    expectNear(bounds.min, {0, 0, 0});
    expectNear(bounds.max, {3, 1, 0});

    // Rotating Root a quarter turn about z carries the whole quad: (1, 0) goes to (0, 1).
    engine::Node& root = scene.nodes[1];
    root.rotation = glm::angleAxis(glm::half_pi<double>(), glm::dvec3(0, 0, 1));
    root.local = root.trsMatrix();
    scene.updateWorldTransforms();
    expectNear(posedVertex(scene, 1), {0, 1, 0});
    // Normals turn with the joints: the quad's +z normal stays +z under a turn about z.
    const glm::vec3 normal = scene.meshInstances[0].deformed->primitives[0].normals[1];
    EXPECT_NEAR(normal.z, 1.0f, 1e-6f);
}

// glTF 2.0 makes inverseBindMatrices optional (each is then the identity); tinygltf 2.7.0
// reports its absence as an error, which the loader must not pass on.
TEST(GltfSkins, ASkinWithoutInverseBindMatricesBindsWithTheIdentity) {
    TempDir dir;
    GltfBuilder b = skinnedQuad();
    b.doc["skins"][0].erase("inverseBindMatrices");
    engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "no_inverse_bind"));
    ASSERT_EQ(scene.skins.size(), 1u);
    for (const glm::dmat4& matrix : scene.skins[0].inverseBindMatrices) EXPECT_EQ(matrix, glm::dmat4(1.0));
    // Root at the origin and Tip at (0, 1, 0) with identity binds: vertex (1, 1, 0), bound to
    // Tip alone, is carried up by Tip's translation to (1, 2, 0).
    expectNear(posedVertex(scene, 2), {1, 2, 0});
}

// One morph target lifting every vertex by (0, 0, 1).
GltfBuilder morphedQuad(const json& meshWeights) {
    GltfBuilder b = quadScene();
    const int lift = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, 3, "VEC3");
    b.doc["meshes"][0]["primitives"][0]["targets"] = json::array({{{"POSITION", lift}}});
    if (!meshWeights.is_null()) b.doc["meshes"][0]["weights"] = meshWeights;
    return b;
}

TEST(GltfSkins, MorphWeightsFromTheMeshThenTheNode) {
    TempDir dir;
    engine::Scene scene = engine::loadGltf(morphedQuad(json::array({0.5})).writeGltf(dir.path(), "morphed"));
    ASSERT_EQ(scene.meshes[0].weights, std::vector<float>{0.5f});
    expectNear(posedVertex(scene, 2), {1, 1, 0.5});
    scene.nodes[0].weights = {1.0f};  // as an animation's weights channel sets them
    scene.updateWorldTransforms();
    expectNear(posedVertex(scene, 2), {1, 1, 1});
    EXPECT_NEAR(scene.meshInstances[0].worldBounds.max.z, 1.0, 1e-6);
}

struct BadDeformer {
    const char* name;
    void (*breakIt)(GltfBuilder&);
    std::vector<std::string> message;
};

TEST(GltfSkins, WhatCannotBePosedIsRefusedNamingFileObjectAndReason) {
    const BadDeformer cases[] = {
        {"joint_past_skin",
         [](GltfBuilder& b) {  // vertex 2 uses joint 1
             b.doc["skins"][0]["joints"] = {1};
             b.doc["skins"][0]["inverseBindMatrices"] =
                 b.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, 16, "MAT4");
         },
         {"joint_past_skin.gltf", "nodes[0] 'Skinned'", "vertex 2", "uses joint 1", "which has 1 joints"}},
        {"joints_without_weights",
         [](GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0"); },
         {"joints_without_weights.gltf", "meshes[0].primitives[0]", "JOINTS_0 without WEIGHTS_0"}},
        {"zero_weights",
         [](GltfBuilder& b) {
             b.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = b.addFloats(std::vector<float>(16, 0.0f), 4, "VEC4");
         },
         {"zero_weights.gltf", "WEIGHTS_0 of vertex 0", "not all 0"}},
        {"inverse_bind_count",
         [](GltfBuilder& b) { b.doc["skins"][0]["joints"] = {1, 2, 0}; },
         {"inverse_bind_count.gltf", "skins[0]", "holds 2 matrices for 3 joints"}},
        {"no_joints", [](GltfBuilder& b) { b.doc["skins"][0]["joints"] = json::array(); },
         {"no_joints.gltf", "skins[0]", "has no joints"}},
        {"joint_missing", [](GltfBuilder& b) { b.doc["skins"][0]["joints"] = {1, 9}; },
         {"joint_missing.gltf", "skins[0]", "joint node 9 does not exist"}},
        {"node_weights_count", [](GltfBuilder& b) { b.doc["nodes"][0]["weights"] = {1, 2}; },
         {"node_weights_count.gltf", "nodes[0] 'Skinned'", "weights has 2 entries for 0 morph targets"}},
    };
    for (const BadDeformer& c : cases) {
        SCOPED_TRACE(c.name);
        TempDir dir;
        GltfBuilder b = skinnedQuad();
        c.breakIt(b);
        expectLoadError(b.writeGltf(dir.path(), c.name), c.message);
    }
    TempDir dir;
    expectLoadError(morphedQuad(json::array({0.5, 0.5})).writeGltf(dir.path(), "mesh_weights"),
                    {"mesh_weights.gltf", "meshes[0]", "weights has 2 entries for 1 morph targets"});
}

} // namespace
