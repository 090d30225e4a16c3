// Scene::updateWorldTransforms and the name lookups, on scenes built by hand.
#include "engine/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <numbers>

namespace {

using engine::Scene;

engine::Mesh unitCubeMesh() {
    engine::Mesh mesh;
    engine::Primitive primitive;
    primitive.positions = {{-1, -1, -1}, {1, 1, 1}, {1, -1, -1}};
    primitive.indices = {0, 1, 2};
    primitive.bounds.extend(glm::dvec3(-1.0));
    primitive.bounds.extend(glm::dvec3(1.0));
    mesh.bounds = primitive.bounds;
    mesh.primitives = {primitive, primitive};
    return mesh;
}

int addNode(Scene& scene, const std::string& name, const glm::dmat4& local, int parent = -1) {
    engine::Node node;
    node.name = name;
    node.local = local;
    node.parent = parent;
    scene.nodes.push_back(node);
    const int index = static_cast<int>(scene.nodes.size() - 1);
    if (parent >= 0) scene.nodes[parent].children.push_back(index);
    else scene.roots.push_back(index);
    return index;
}

glm::dmat4 translation(double x, double y, double z) { return glm::translate(glm::dmat4(1.0), {x, y, z}); }

TEST(SceneGraph, WorldIsParentWorldTimesLocalInDouble) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    // Far from the origin, where float would lose the child's 1e-3 offset (float spacing
    // at 1e6 is 0.0625): composition must stay in double.
    const int parent = addNode(scene, "parent", translation(1e6, 0, 0));
    const int child = addNode(scene, "child", translation(1e-3, 2, 0), parent);
    scene.nodes[child].mesh = 0;
    scene.updateWorldTransforms();

    EXPECT_EQ(scene.nodes[child].world[3][0], 1e6 + 1e-3);
    EXPECT_EQ(scene.nodes[child].world[3][1], 2.0);
    ASSERT_EQ(scene.meshInstances.size(), 1u);
    EXPECT_EQ(scene.meshInstances[0].node, child);
    EXPECT_EQ(scene.meshInstances[0].world, scene.nodes[child].world);
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.min.x, 1e6 + 1e-3 - 1);
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.max.x, 1e6 + 1e-3 + 1);
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.min.y, 1.0);
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.max.y, 3.0);
}

TEST(SceneGraph, WorldBoundsCoverRotatedInstances) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    const glm::dmat4 rotated = glm::rotate(glm::dmat4(1.0), std::numbers::pi / 4, glm::dvec3(0, 0, 1));
    const int a = addNode(scene, "a", rotated);
    const int b = addNode(scene, "b", translation(10, 0, 0));
    scene.nodes[a].mesh = scene.nodes[b].mesh = 0;
    scene.updateWorldTransforms();

    const double r = std::sqrt(2.0);  // the rotated cube's half extent along x and y
    EXPECT_NEAR(scene.worldBounds.min.x, -r, 1e-12);
    EXPECT_NEAR(scene.worldBounds.min.y, -r, 1e-12);
    EXPECT_NEAR(scene.worldBounds.max.x, 11.0, 1e-12);
    EXPECT_NEAR(scene.worldBounds.max.y, r, 1e-12);
    EXPECT_NEAR(scene.worldBounds.max.z, 1.0, 1e-12);
}

TEST(SceneGraph, InstancesAreListedDepthFirstFromTheRoots) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    const int root1 = addNode(scene, "root1", glm::dmat4(1.0));
    const int root2 = addNode(scene, "root2", glm::dmat4(1.0));
    const int child1 = addNode(scene, "child1", glm::dmat4(1.0), root1);
    const int grandchild = addNode(scene, "grandchild", glm::dmat4(1.0), child1);
    const int child2 = addNode(scene, "child2", glm::dmat4(1.0), root1);
    for (engine::Node& node : scene.nodes) node.mesh = 0;
    scene.updateWorldTransforms();

    std::vector<int> order;
    for (const engine::MeshInstance& instance : scene.meshInstances) order.push_back(instance.node);
    EXPECT_EQ(order, (std::vector<int>{root1, child1, grandchild, child2, root2}));
}

TEST(SceneGraph, NodesOutsideTheDisplayedSceneHaveNoInstances) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    addNode(scene, "shown", glm::dmat4(1.0));
    scene.nodes.push_back(engine::Node{});  // not a root, not a child: not displayed
    scene.nodes.back().mesh = 0;
    scene.updateWorldTransforms();
    EXPECT_TRUE(scene.meshInstances.empty());
    EXPECT_TRUE(scene.worldBounds.empty());
}

TEST(SceneGraph, InstancesCopyTheNodesShadowFlags) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    const int caster = addNode(scene, "caster", glm::dmat4(1.0));
    const int floor = addNode(scene, "floor", glm::dmat4(1.0));
    scene.nodes[caster].mesh = scene.nodes[floor].mesh = 0;
    scene.nodes[caster].receiveShadows = false;
    scene.nodes[floor].castShadows = false;
    scene.updateWorldTransforms();

    ASSERT_EQ(scene.meshInstances.size(), 2u);
    EXPECT_TRUE(scene.meshInstances[0].castShadows);
    EXPECT_FALSE(scene.meshInstances[0].receiveShadows);
    EXPECT_FALSE(scene.meshInstances[1].castShadows);
    EXPECT_TRUE(scene.meshInstances[1].receiveShadows);
}

TEST(SceneGraph, UpdateRebuildsTheInstanceLists) {
    Scene scene;
    scene.meshes.push_back(unitCubeMesh());
    const int node = addNode(scene, "n", glm::dmat4(1.0));
    scene.nodes[node].mesh = 0;
    scene.updateWorldTransforms();
    scene.nodes[node].local = translation(5, 0, 0);
    scene.updateWorldTransforms();
    ASSERT_EQ(scene.meshInstances.size(), 1u);
    EXPECT_EQ(scene.meshInstances[0].world[3][0], 5.0);
    EXPECT_EQ(scene.worldBounds.min.x, 4.0);
}

TEST(SceneGraph, LightsAndCamerasLookDownTheirNodesMinusZ) {
    Scene scene;
    scene.lights.push_back({});
    scene.cameras.push_back({});
    // Rotating -90 degrees about x turns -z into -y: a light pointing straight down.
    const glm::dmat4 down = translation(0, 10, 0) *
                            glm::rotate(glm::dmat4(1.0), -std::numbers::pi / 2, glm::dvec3(1, 0, 0));
    const int lightNode = addNode(scene, "sun", down);
    const int cameraNode = addNode(scene, "eye", translation(0, 1, 5));
    scene.nodes[lightNode].light = 0;
    scene.nodes[cameraNode].camera = 0;
    scene.updateWorldTransforms();

    ASSERT_EQ(scene.lightInstances.size(), 1u);
    EXPECT_NEAR(scene.lightInstances[0].position().y, 10.0, 1e-12);
    EXPECT_NEAR(scene.lightInstances[0].direction().y, -1.0, 1e-12);
    ASSERT_EQ(scene.cameraInstances.size(), 1u);
    EXPECT_EQ(scene.cameraInstances[0].world[3][2], 5.0);
}

TEST(SceneGraph, FindsLightsByLightNameThenByNodeName) {
    Scene scene;
    scene.lights.resize(2);
    scene.lights[0].name = "key";
    scene.lights[1].name = "";  // unnamed light: found by its node's name
    const int a = addNode(scene, "fill", glm::dmat4(1.0));
    const int b = addNode(scene, "rim", glm::dmat4(1.0));
    const int c = addNode(scene, "key_node", glm::dmat4(1.0));
    scene.nodes[a].light = 1;
    scene.nodes[b].light = 1;
    scene.nodes[c].light = 0;
    scene.updateWorldTransforms();

    EXPECT_EQ(scene.findLightInstance("key"), 2);  // the light's name wins
    EXPECT_EQ(scene.findLightInstance("rim"), 1);
    EXPECT_EQ(scene.findLightInstance("fill"), 0);
    EXPECT_EQ(scene.findLightInstance("absent"), -1);
}

TEST(SceneGraph, FindsCamerasByCameraNameThenByNodeName) {
    Scene scene;
    scene.cameras.resize(2);
    scene.cameras[0].name = "main";
    const int a = addNode(scene, "front", glm::dmat4(1.0));
    const int b = addNode(scene, "side", glm::dmat4(1.0));
    scene.nodes[a].camera = 1;
    scene.nodes[b].camera = 0;
    scene.updateWorldTransforms();

    EXPECT_EQ(scene.findCameraInstance("main"), 1);
    EXPECT_EQ(scene.findCameraInstance("front"), 0);
    EXPECT_EQ(scene.findCameraInstance("top"), -1);
}

TEST(SceneGraph, MeshTriangleCountSumsItsPrimitives) {
    EXPECT_EQ(unitCubeMesh().triangleCount(), 2u);
    EXPECT_EQ(engine::Mesh{}.triangleCount(), 0u);
}

} // namespace
