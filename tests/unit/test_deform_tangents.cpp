// deformMesh (Deform.h) on tangents, with scenes built in code: morph target offsets move a
// tangent's xyz; a joint turns it as it turns the surface, by the joint matrix itself (not
// by the inverse transpose the normals take); w never changes; a primitive without tangents
// poses none.
#include "engine/scene/Deform.h"
#include "engine/scene/Scene.h"
#include "engine/scene/Shapes.h"
#include "../support/TangentExpectations.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using engine::test::expectTangent;

namespace {

// A unit quad facing +z, every vertex's tangent `tangent`, bound wholly to joint 0.
engine::Primitive skinnedQuad(const glm::vec4& tangent) {
    engine::Primitive primitive = engine::texturedQuadPrimitive({0.0, 0.0}, {1.0, 1.0});
    primitive.tangents.assign(4, tangent);
    primitive.joints.assign(4, glm::uvec4(0));
    primitive.weights.assign(4, glm::vec4(1, 0, 0, 0));
    return primitive;
}

// Node 0 shows mesh 0 skinned by skin 0, whose one joint is node 1 with local transform
// `joint` (inverse bind matrix identity).
engine::Scene skinnedScene(engine::Primitive primitive, const glm::dmat4& joint) {
    engine::Scene scene;
    engine::Mesh mesh;
    mesh.primitives.push_back(std::move(primitive));
    scene.meshes.push_back(std::move(mesh));
    scene.skins.push_back({"skin", {1}, {glm::dmat4(1.0)}});
    engine::Node skinned;
    skinned.mesh = 0;
    skinned.skin = 0;
    engine::Node bone;
    bone.local = joint;
    scene.nodes = {skinned, bone};
    scene.roots = {0, 1};
    scene.updateWorldTransforms();
    return scene;
}

} // namespace

// A quarter turn about +z carries the tangent +x to +y; the sign stays.
TEST(DeformTangents, AJointTurnsTheTangents) {
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::half_pi<double>(), glm::dvec3(0, 0, 1));
    const engine::Scene scene = skinnedScene(skinnedQuad({1, 0, 0, -1}), turn);
    const engine::DeformedMesh pose = engine::deformMesh(scene, scene.nodes[0]);
    ASSERT_EQ(pose.primitives.at(0).tangents.size(), 4u);
    for (const glm::vec4& tangent : pose.primitives[0].tangents) expectTangent(tangent, {0, 1, 0}, -1.0f);
}

// Under a non-uniform scale (x doubled) the surface's diagonal (1, 1, 0) becomes (2, 1, 0):
// tangents go with the surface. The inverse transpose (the normals' matrix) would give
// (0.5, 1, 0), a direction no longer along the stretched surface's UV gradient.
TEST(DeformTangents, AJointScalesTheTangentsAsTheSurfaceNotAsTheNormals) {
    const glm::dmat4 stretch = glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1));
    const engine::Scene scene = skinnedScene(skinnedQuad({0.70710678f, 0.70710678f, 0, 1}), stretch);
    const engine::DeformedMesh pose = engine::deformMesh(scene, scene.nodes[0]);
    ASSERT_EQ(pose.primitives.at(0).tangents.size(), 4u);
    expectTangent(pose.primitives[0].tangents[2], glm::vec3(2, 1, 0) / std::sqrt(5.0f), 1.0f);
    // The normals still take the inverse transpose: +z stays +z.
    EXPECT_NEAR(pose.primitives[0].normals[2].z, 1.0f, 1e-6f);
}

// Morph first, then skin: +x moved by 0.5 * (-2, 2, 0) is +y, turned a quarter about +z
// is -x.
TEST(DeformTangents, MorphOffsetsMoveTheTangentsBeforeTheJointsTurnThem) {
    engine::Primitive primitive = skinnedQuad({1, 0, 0, 1});
    engine::MorphTarget target;
    target.positions.assign(4, glm::vec3(0.0f));
    target.tangents.assign(4, glm::vec3(-2, 2, 0));
    primitive.targets.push_back(target);
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::half_pi<double>(), glm::dvec3(0, 0, 1));
    engine::Scene scene = skinnedScene(primitive, turn);
    scene.meshes[0].weights = {0.5f};
    const engine::DeformedMesh pose = engine::deformMesh(scene, scene.nodes[0]);
    ASSERT_EQ(pose.primitives.at(0).tangents.size(), 4u);
    for (const glm::vec4& tangent : pose.primitives[0].tangents) expectTangent(tangent, {-1, 0, 0}, 1.0f);
}

// Morph alone (no skin): the node's weights override the mesh's.
TEST(DeformTangents, MorphedTangentsFollowTheNodesWeights) {
    engine::Scene scene;
    engine::Mesh mesh;
    engine::Primitive primitive = engine::texturedQuadPrimitive({0.0, 0.0}, {1.0, 1.0});
    primitive.tangents.assign(4, glm::vec4(1, 0, 0, -1));
    engine::MorphTarget target;
    target.positions.assign(4, glm::vec3(0.0f));
    target.tangents.assign(4, glm::vec3(-1, 0, 1));
    primitive.targets.push_back(target);
    mesh.primitives.push_back(primitive);
    mesh.weights = {0.0f};
    scene.meshes.push_back(mesh);
    engine::Node node;
    node.mesh = 0;
    node.weights = {1.0f};
    scene.nodes = {node};
    scene.roots = {0};
    const engine::DeformedMesh pose = engine::deformMesh(scene, scene.nodes[0]);
    ASSERT_EQ(pose.primitives.at(0).tangents.size(), 4u);
    expectTangent(pose.primitives[0].tangents[0], {0, 0, 1}, -1.0f);
}

TEST(DeformTangents, APrimitiveWithoutTangentsPosesNone) {
    engine::Primitive primitive = skinnedQuad({1, 0, 0, 1});
    primitive.tangents.clear();
    const engine::Scene scene = skinnedScene(primitive, glm::dmat4(1.0));
    const engine::DeformedMesh pose = engine::deformMesh(scene, scene.nodes[0]);
    ASSERT_EQ(pose.primitives.size(), 1u);
    EXPECT_TRUE(pose.primitives[0].tangents.empty());
    EXPECT_EQ(pose.primitives[0].normals.size(), 4u);
}
