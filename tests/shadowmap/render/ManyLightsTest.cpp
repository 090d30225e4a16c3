// Scenes with as many lights as the lit pass takes (kMaxLights), a grid of spot lights each
// over its own patch of floor: every light lights its patch (the image darkens there
// without it), lights past the sixteenth cast their box's shadow, and a scene with more
// lights than the limit names the ones left out. (Up to 16 lights was the old limit: the
// 17th and later lit nothing and cast nothing.)
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/scene/SceneNames.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

// 8 x 4 lights, 4 units apart, 5 above the floor, cone 0.35 rad: each lights a disc of
// radius 5 tan(0.35) = 1.8 < 2, so no two patches overlap.
constexpr int kColumns = 8;
constexpr double kSpacing = 4.0, kLightHeight = 5.0, kCone = 0.35;
// With boxes: one beside each light's foot, x from 0.7 to 1.1 past it, |z| < 0.2, 2 to 2.5
// above the floor. Floor points at x = p (z = 0) see the light past the box's height h at
// x = p (5 - h) / 5, so the box shadows p from 0.7 * 5 / 3 = 1.17 to 1.1 * 5 / 2.5 = 2.2,
// past the lit disc's rim at 1.8; the camera, looking straight down, sees the floor there.
constexpr double kBoxNear = 0.7, kBoxFar = 1.1, kBoxHalfWidth = 0.2, kBoxBottom = 2.0, kBoxTop = 2.5;

glm::dvec3 footOf(int light) {
    return {-14.0 + kSpacing * (light % kColumns), 0.0, -6.0 + kSpacing * (light / kColumns)};
}

engine::Scene gridOfLights(int count, bool boxes) {
    SceneBuilder builder;
    builder.addBox("floor", {-20, -0.2, -20}, {20, 0, 20});
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 foot = footOf(i);
        if (boxes)
            builder.addBox("box_" + std::to_string(i + 1), foot + glm::dvec3(kBoxNear, kBoxBottom, -kBoxHalfWidth),
                           foot + glm::dvec3(kBoxFar, kBoxTop, kBoxHalfWidth));
        builder.addLight("lamp_" + std::to_string(i + 1), Light::Type::Spot, foot + glm::dvec3(0, kLightHeight, 0),
                         foot, {{"resolution", 256}}, kCone);
    }
    return builder.build();
}

// Straight down over the grid, orthographic (a box hides only the floor under it):
// 128 x 64 pixels of 34 / 128 = 0.27 units.
engine::FrameCamera topCamera() {
    engine::FrameCamera camera = engine::test::cameraLooking({0, 30, 0}, {0, 0, 0}, 128, 64);
    camera.projection = glm::ortho(-17.0, 17.0, -8.5, 8.5, 0.1, 100.0);
    return camera;
}

// The pixel showing world point p.
std::size_t pixelOf(const engine::FrameCamera& camera, const glm::dvec3& p) {
    const glm::dvec4 clip = camera.projection * glm::inverse(camera.eyeToWorld) * glm::dvec4(p, 1.0);
    const int x = static_cast<int>((clip.x / clip.w * 0.5 + 0.5) * camera.width);
    const int y = static_cast<int>((0.5 - clip.y / clip.w * 0.5) * camera.height);
    return static_cast<std::size_t>(y) * camera.width + x;
}

class ManyLightsTest : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin(nlohmann::json::object()); }
};

} // namespace

TEST_F(ManyLightsTest, EveryLightUpToTheLimitLightsItsPatch) {
    // At least the 20 lamps of a modest interior, whatever the limit says.
    const int lightCount = std::max(20, engine::kMaxLights);
    engine::Scene scene = gridOfLights(lightCount, false);
    engine::Renderer renderer({}, plugins());
    engine::FrameRequest request;
    request.camera = topCamera();
    renderer.setScene(scene);
    renderer.renderFrame(request);
    const std::vector<std::uint8_t> all = renderer.readColor();
    // The lit pass reads the lights' colour and intensity from the scene every frame: one
    // upload and one program for all these frames.
    for (int light = 0; light < lightCount; ++light) {
        scene.lights[light].intensity = 0.0f;
        renderer.renderFrame(request);
        const std::vector<std::uint8_t> without = renderer.readColor();
        scene.lights[light].intensity = 10.0f;
        // Pixels that lose more than 8/255 of red without the light: its patch is about 140
        // pixels (a disc of radius 1.8 in 0.27-unit pixels); 10 says the light was there.
        int darker = 0;
        for (std::size_t i = 0; i < all.size(); i += 4) darker += all[i] > without[i] + 8;
        EXPECT_GT(darker, 10) << "lamp_" << light + 1 << " lights nothing";
    }
}

TEST_F(ManyLightsTest, LightsPastTheSixteenthCastShadows) {
    const engine::Scene scene = gridOfLights(24, true);
    const engine::FrameCamera camera = topCamera();
    for (int slot : {16, 23}) {
        const std::vector<std::uint8_t> mask = engine::test::renderShadowMask(plugins(), scene, camera, slot);
        const glm::dvec3 foot = footOf(slot);
        // Inside the lit disc: the floor at x = 1.45 past the foot is in the box's shadow
        // (its pixel spans 1.31 to 1.59, inside 1.17 to 1.8), at x = -1.0 it is lit.
        EXPECT_EQ(mask[pixelOf(camera, foot + glm::dvec3(1.45, 0, 0))], 0) << "slot " << slot;
        EXPECT_EQ(mask[pixelOf(camera, foot + glm::dvec3(-1.0, 0, 0))], 255) << "slot " << slot;
    }
}

TEST(LightsPastTheLimit, NamesTheLightsLeftOut) {
    const engine::Scene scene = gridOfLights(engine::kMaxLights + 2, false);
    EXPECT_EQ(engine::lightsPastTheLimit(scene, engine::kMaxLights),
              "the scene has " + std::to_string(engine::kMaxLights + 2) + " lights; only the first " +
                  std::to_string(engine::kMaxLights) + " are rendered, not: " +
                  std::to_string(engine::kMaxLights + 1) + " lamp_" + std::to_string(engine::kMaxLights + 1) +
                  ", " + std::to_string(engine::kMaxLights + 2) + " lamp_" +
                  std::to_string(engine::kMaxLights + 2));
    EXPECT_EQ(engine::lightsPastTheLimit(gridOfLights(3, false), engine::kMaxLights), "");
}
