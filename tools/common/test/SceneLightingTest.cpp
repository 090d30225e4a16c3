// The key light and ground every tool adds the same way (tools/common/SceneLighting.h): no
// GL, a one-box scene built in memory.
#include "SceneLighting.h"

#include "engine/scene/Framing.h"
#include "engine/scene/Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

// A unit box standing on y = 2 (bounds (0, 2, 0) .. (1, 3, 1)), no light.
engine::Scene boxScene() {
    engine::Scene scene;
    engine::Primitive box;
    for (int i = 0; i < 8; ++i) box.positions.push_back(glm::vec3(i & 1, 2 + ((i >> 1) & 1), (i >> 2) & 1));
    box.normals.assign(8, glm::vec3(0.0f, 1.0f, 0.0f));
    box.indices = {0, 1, 2, 1, 3, 2};
    for (const glm::vec3& p : box.positions) box.bounds.extend(glm::dvec3(p));
    engine::Mesh mesh;
    mesh.bounds = box.bounds;
    mesh.primitives.push_back(box);
    scene.meshes.push_back(mesh);
    engine::Node node;
    node.name = "box";
    node.mesh = 0;
    scene.nodes.push_back(node);
    scene.roots.push_back(0);
    scene.updateWorldTransforms();
    return scene;
}

TEST(SceneLighting, ASceneWithoutLightIsWarnedAbout) {
    engine::Scene scene = boxScene();
    const tools::StagedScene staged = tools::stageScene(scene, "box.gltf", {});
    ASSERT_EQ(staged.warnings.size(), 1u);
    EXPECT_NE(staged.warnings[0].find("box.gltf: the scene has no lights"), std::string::npos);
    EXPECT_NE(staged.warnings[0].find("--key-light"), std::string::npos);
    EXPECT_TRUE(staged.notes.empty());
    EXPECT_EQ(scene.nodes.size(), 1u);  // nothing added unasked
}

TEST(SceneLighting, KeyLightIsPlacedAndSaysWhere) {
    engine::Scene scene = boxScene();
    tools::SceneLighting lighting;
    lighting.keyLight = engine::Light::Type::Spot;
    const tools::StagedScene staged = tools::stageScene(scene, "box.gltf", lighting);
    EXPECT_TRUE(staged.warnings.empty());
    ASSERT_EQ(scene.lightInstances.size(), 1u);
    ASSERT_EQ(staged.notes.size(), 1u);
    // Above the box (the placement is engine::addKeyLight's), aimed at its centre.
    EXPECT_GT(scene.lightInstances[0].position().y, 3.0);
    EXPECT_EQ(staged.notes[0].rfind("key light: spot \"key_light\" at (", 0), 0u) << staged.notes[0];
    EXPECT_NE(staged.notes[0].find("aimed at (0.5, 2.5, 0.5)"), std::string::npos) << staged.notes[0];
    EXPECT_NE(staged.notes[0].find("cone"), std::string::npos);
}

TEST(SceneLighting, GroundLiesUnderTheModelAndOnlyReceives) {
    engine::Scene scene = boxScene();
    tools::SceneLighting lighting;
    lighting.keyLight = engine::Light::Type::Point;
    lighting.ground = true;
    const tools::StagedScene staged = tools::stageScene(scene, "box.gltf", lighting);
    ASSERT_EQ(scene.meshInstances.size(), 2u);
    const engine::MeshInstance& ground = scene.meshInstances.back();
    EXPECT_FALSE(ground.castShadows);
    EXPECT_TRUE(ground.receiveShadows);
    // Flat, just under the box's bottom (y = 2) by 1e-3 of the box's radius (sqrt(3)/2),
    // and wider than the box on both horizontal axes.
    EXPECT_DOUBLE_EQ(ground.worldBounds.min.y, ground.worldBounds.max.y);
    EXPECT_NEAR(ground.worldBounds.min.y, 2.0 - 1e-3 * std::sqrt(3.0) / 2.0, 1e-9);
    EXPECT_LT(ground.worldBounds.min.x, 0.0);
    EXPECT_GT(ground.worldBounds.max.z, 1.0);
    // It faces up, towards the light: its triangles wind counter-clockwise seen from +Y.
    const engine::Primitive& quad = scene.meshes[ground.mesh].primitives[0];
    for (std::size_t i = 0; i < quad.indices.size(); i += 3) {
        const glm::vec3 a = quad.positions[quad.indices[i]], b = quad.positions[quad.indices[i + 1]],
                        c = quad.positions[quad.indices[i + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
    }
    ASSERT_EQ(staged.notes.size(), 2u);
    EXPECT_EQ(staged.notes[1].rfind("ground: (", 0), 0u) << staged.notes[1];
}

TEST(SceneLighting, FlagsAreTakenOthersLeft) {
    tools::SceneLighting lighting;
    EXPECT_TRUE(tools::parseSceneLightingFlag(lighting, "--key-light", "directional"));
    EXPECT_TRUE(tools::parseSceneLightingFlag(lighting, "--ground", ""));
    EXPECT_FALSE(tools::parseSceneLightingFlag(lighting, "--width", "3"));
    EXPECT_EQ(lighting.keyLight, engine::Light::Type::Directional);
    EXPECT_TRUE(lighting.ground);
    EXPECT_THROW(tools::parseSceneLightingFlag(lighting, "--key-light", "sun"), std::invalid_argument);
}

// The key light's angles are from the framing view (engine/scene/Framing.h): azimuth 0 is
// the camera's own side, 90 its right, elevation 90 straight up; --key-light-angles sets them.
TEST(SceneLighting, KeyLightAnglesAreTakenFromTheFramingView) {
    const glm::dvec3 view = engine::framingViewDirection();
    const glm::dvec3 side = glm::normalize(glm::dvec3(view.x, 0.0, view.z));
    const glm::dvec3 right = glm::normalize(glm::cross(-view, glm::dvec3(0.0, 1.0, 0.0)));
    constexpr double kRounding = 1e-12;  // a few double roundings of sin/cos on unit vectors
    const auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < kRounding; };
    EXPECT_TRUE(near(engine::keyLightDirection({0.0, 0.0}), side));
    EXPECT_TRUE(near(engine::keyLightDirection({90.0, 0.0}), right));
    EXPECT_TRUE(near(engine::keyLightDirection({-90.0, 0.0}), -right));
    EXPECT_TRUE(near(engine::keyLightDirection({30.0, 90.0}), glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 defaults = engine::keyLightDirection({});
    EXPECT_NEAR(glm::degrees(std::asin(defaults.y)), engine::KeyLightAngles{}.elevationDegrees, 1e-9);

    tools::SceneLighting lighting;
    EXPECT_TRUE(tools::parseSceneLightingFlag(lighting, "--key-light-angles", "-30,60"));
    EXPECT_EQ(lighting.keyLightAngles.azimuthDegrees, -30.0);
    EXPECT_EQ(lighting.keyLightAngles.elevationDegrees, 60.0);
    for (const char* bad : {"30", "30,0", "30,91", "200,45", "30,45,1", "east,45"})
        EXPECT_THROW(tools::parseSceneLightingFlag(lighting, "--key-light-angles", bad), std::invalid_argument) << bad;

    lighting.keyLight = engine::Light::Type::Directional;
    engine::Scene scene = boxScene();
    tools::stageScene(scene, "box.gltf", lighting);
    ASSERT_EQ(scene.lightInstances.size(), 1u);
    // A directional light shines from its direction toward the centre.
    EXPECT_TRUE(glm::length(-scene.lightInstances[0].direction() - engine::keyLightDirection({-30.0, 60.0})) < 1e-9);
}

} // namespace
