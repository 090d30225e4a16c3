// The lit pass's draw order: only instances the camera's frustum touches, nearest first by
// the distance to their bounds, ties in scene order; unchanged 10^6 from the origin.
#include "engine/scene/DrawOrder.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace {


engine::MeshInstance instanceAt(glm::dvec3 min, glm::dvec3 max) {
    engine::MeshInstance instance;
    instance.worldBounds.extend(min);
    instance.worldBounds.extend(max);
    return instance;
}

// A camera at `eye` looking down -Z with a 90 degree perspective, near 0.1, far 100.
glm::dmat4 viewProjectionAt(const glm::dvec3& eye) {
    return glm::perspectiveRH_NO(glm::half_pi<double>(), 1.0, 0.1, 100.0) *
           glm::translate(glm::dmat4(1.0), -eye);
}

TEST(DrawOrder, VisibleInstancesNearestFirstTiesInSceneOrder) {
    for (const glm::dvec3 eye : {glm::dvec3(0.0), glm::dvec3(1e6, -2e6, 3e6)}) {
        engine::Scene scene;
        auto add = [&](glm::dvec3 min, glm::dvec3 max) {
            scene.meshInstances.push_back(instanceAt(min + eye, max + eye));
        };
        add({-1, -1, -21}, {1, 1, -19});   // 0: far
        add({-1, -1, 4}, {1, 1, 6});       // 1: behind the camera: culled
        add({-1, -1, -6}, {1, 1, -4});     // 2: nearest box in front
        add({2, -1, -11}, {4, 1, -9});     // 3: right, as far as 4
        add({-4, -1, -11}, {-2, 1, -9});   // 4: left, mirror image of 3
        add({-50, -2, -50}, {50, -1, 50}); // 5: a floor under the camera: 1 below the eye
        add({-1, -1, -300}, {1, 1, -250}); // 6: beyond the far plane: culled

        const engine::DrawOrder order = engine::nearestFirst(scene, viewProjectionAt(eye), eye);
        EXPECT_EQ(order.culled, 2);
        EXPECT_EQ(order.instances, (std::vector<int>{5, 2, 3, 4, 0})) << "eye " << eye.x;
    }
}

TEST(DrawOrder, CameraInsideABoundsDrawsItFirst) {
    engine::Scene scene;
    scene.meshInstances.push_back(instanceAt({-1, -1, -3}, {1, 1, -2}));
    scene.meshInstances.push_back(instanceAt({-10, -10, -10}, {10, 10, 10}));  // a room
    const engine::DrawOrder order = engine::nearestFirst(scene, viewProjectionAt({0, 0, 0}), {0, 0, 0});
    EXPECT_EQ(order.culled, 0);
    EXPECT_EQ(order.instances, (std::vector<int>{1, 0}));
}

TEST(DrawOrder, EmptySceneAndEmptyBounds) {
    engine::Scene scene;
    EXPECT_TRUE(engine::nearestFirst(scene, viewProjectionAt({0, 0, 0}), {0, 0, 0}).instances.empty());
    scene.meshInstances.push_back(engine::MeshInstance{});  // no bounds: nothing to draw
    const engine::DrawOrder order = engine::nearestFirst(scene, viewProjectionAt({0, 0, 0}), {0, 0, 0});
    EXPECT_TRUE(order.instances.empty());
    EXPECT_EQ(order.culled, 1);
}

}  // namespace
