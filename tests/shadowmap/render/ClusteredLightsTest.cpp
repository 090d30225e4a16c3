// The clustered lit pass (engine/render/Frame.h, kMaxClusteredLights) with the shadow
// plugin's atlas (plugin/AtlasMaps.h): a scene with more lights than the unrolled pass takes
// renders every one of them shadowed, each lamp's mask matching the analytic shadow as the
// single-light tests require; a still frame draws no map again and a moved lamp only its
// own; and the loop over a tile's lights sums what the unrolled pass sums.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

// 8 x 8 lamps 4 units apart, 5 above a floor; a box beside each lamp's foot (x 0.5 to 1.0
// past it, |z| < 0.5, 2.5 to 3 high) shadows the floor in its pool from x = 0.5 * 5 / 2.5 =
// 1 to 1.0 * 5 / 2 = 2.5, inside the lit disc (cone 0.5: radius 5 tan 0.5 = 2.73).
constexpr int kColumns = 8;
constexpr double kSpacing = 4.0, kLightHeight = 5.0, kCone = 0.5;

glm::dvec3 footOf(int lamp) { return {-14.0 + kSpacing * (lamp % kColumns), 0.0, -14.0 + kSpacing * (lamp / kColumns)}; }

struct Street {
    engine::Scene scene;
    std::vector<engine::Aabb> occluders;  // the floor and every box
    std::vector<int> lampNodes;
};

Street lampGrid(int count, const nlohmann::json& shadow) {
    SceneBuilder builder;
    Street street;
    street.occluders.push_back({{-17, -0.2, -17}, {17, 0, 17}});
    builder.addBox("floor", street.occluders.back().min, street.occluders.back().max);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 foot = footOf(i);
        street.occluders.push_back({foot + glm::dvec3(0.5, 2.5, -0.5), foot + glm::dvec3(1.0, 3.0, 0.5)});
        builder.addBox("box_" + std::to_string(i + 1), street.occluders.back().min, street.occluders.back().max);
        street.lampNodes.push_back(builder.addLight("lamp_" + std::to_string(i + 1), Light::Type::Spot,
                                                    foot + glm::dvec3(0, kLightHeight, 0), foot, shadow, kCone));
    }
    street.scene = builder.build();
    return street;
}

// Straight down over the grid, orthographic: 384 x 384 pixels of 34 / 384 = 0.089 units.
engine::FrameCamera topCamera() {
    engine::FrameCamera camera = engine::test::cameraLooking({0, 30, 0.001}, {0, 0, 0}, 384, 384);
    camera.projection = glm::ortho(-17.0, 17.0, -17.0, 17.0, 0.1, 100.0);
    return camera;
}

class ClusteredLightsTest : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin(nlohmann::json::object()); }
};

} // namespace

TEST_F(ClusteredLightsTest, SixtyFourLampsEachMatchTheirAnalyticShadow) {
    const Street street = lampGrid(64, {{"resolution", 512}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(street.scene);
    engine::FrameRequest request;
    request.camera = topCamera();
    for (int slot = 0; slot < 64; ++slot) request.shadowMaskSlots.push_back(slot);
    const engine::FrameResult result = renderer.renderFrame(request);
    ASSERT_TRUE(result.clusteredLights) << "64 lights must take the clustered pass";
    const nlohmann::json& atlas = result.pluginStats.at("shadowmap_plugin").at("atlas");
    EXPECT_EQ(atlas.at("maps"), 64);
    EXPECT_EQ(atlas.at("rendered"), 64);
    for (int slot = 0; slot < 64; ++slot) {
        const engine::LightInstance& placed = street.scene.lightInstances[slot];
        const auto inCone = [&](const glm::dvec3& p) {
            return std::acos(glm::dot(glm::normalize(p - placed.position()), placed.direction())) < kCone - 0.03;
        };
        const engine::test::MaskStats stats = engine::test::compareFloorMask(
            renderer.readShadowMask(slot), street.scene, slot, request.camera, street.occluders, 0.0, 16.9, inCone);
        // The pool's shadow is about 1.5 x 1.6 units (250 pixels), its lit rest ~2500.
        EXPECT_GT(stats.truthShadowed, 100) << "lamp_" << slot + 1;
        EXPECT_GT(stats.truthLit, 1000) << "lamp_" << slot + 1;
        // The single-light tests' bound (ShadowMaskTest: 0.3 % of the evaluated pixels).
        EXPECT_LE(stats.wrongFraction(), 0.003) << "lamp_" << slot + 1;
    }
}

TEST_F(ClusteredLightsTest, AStillFrameDrawsNoMapAndAMovedLampOnlyItsOwn) {
    Street street = lampGrid(40, {{"resolution", 256}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(street.scene);
    engine::FrameRequest request;
    request.camera = topCamera();
    const auto atlasOf = [](const engine::FrameResult& frame) {
        return frame.pluginStats.at("shadowmap_plugin").at("atlas");
    };
    EXPECT_EQ(atlasOf(renderer.renderFrame(request)).at("rendered"), 40);
    const nlohmann::json still = atlasOf(renderer.renderFrame(request));
    EXPECT_EQ(still.at("rendered"), 0);
    EXPECT_EQ(still.at("cached"), 40);
    // A swinging lamp: its node turns a little.
    engine::Node& lamp = street.scene.nodes[street.lampNodes[17]];
    lamp.local = lamp.local * glm::rotate(glm::dmat4(1.0), 0.05, glm::dvec3(1, 0, 0));
    street.scene.updateWorldTransforms();
    const nlohmann::json swung = atlasOf(renderer.renderFrame(request));
    EXPECT_EQ(swung.at("rendered"), 1);
    EXPECT_EQ(swung.at("cached"), 39);
}

TEST_F(ClusteredLightsTest, TheTileLoopSumsWhatTheUnrolledPassSums) {
    // 30 unshadowed lamps (their pools overlap: cone 0.5, 4 apart) seen in perspective, shaded
    // by both passes in one run: each pixel's tile list must hold every lamp that lights it,
    // or the loop's sum falls short there. The sums differ only by float rounding in another
    // order: within 1/255 per channel after the sRGB encoding.
    const Street street = lampGrid(30, {{"variant", "none"}});
    engine::FrameRequest request;
    request.camera = engine::test::cameraLooking({-20, 14, -20}, {0, 0, -4}, 320, 180);
    std::vector<std::vector<std::uint8_t>> images;
    for (const bool clustered : {false, true}) {
        engine::RendererConfig config;
        config.clusteredLights = clustered;
        engine::Renderer renderer(config, plugins());
        renderer.setScene(street.scene);
        const engine::FrameResult result = renderer.renderFrame(request);
        EXPECT_EQ(result.clusteredLights, clustered);
        if (clustered) EXPECT_GT(result.tileListEntries, 0);
        images.push_back(renderer.readColor());
    }
    int largest = 0, lit = 0;
    for (std::size_t i = 0; i < images[0].size(); ++i) {
        largest = std::max(largest, std::abs(int(images[0][i]) - int(images[1][i])));
        lit += i % 4 == 0 && images[0][i] > 40;
    }
    EXPECT_LE(largest, 1);
    EXPECT_GT(lit, 5000) << "too little of the image is lit to compare";
}

TEST_F(ClusteredLightsTest, ANearLampGetsALargerMapThanAFarOneAndNoneMoreThanItAsked) {
    const Street street = lampGrid(40, {{"resolution", 1024}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(street.scene);
    engine::FrameRequest request;
    // Low beside the first lamp's pool, looking across the grid: the last lamp is 30 units away.
    request.camera = engine::test::cameraLooking(footOf(0) + glm::dvec3(-3, 2, -3), footOf(0), 640, 360);
    const engine::FrameResult result = renderer.renderFrame(request);
    const nlohmann::json& lights = result.pluginStats.at("shadowmap_plugin").at("lights");
    const auto sizeOf = [&](int slot) { return lights.at(slot).at("resolution").get<int>(); };
    // Blocks are powers of two with a one-texel border: 1022 is the largest map not above 1024.
    for (int slot = 0; slot < 40; ++slot) EXPECT_LE(sizeOf(slot), 1022) << "lamp_" << slot + 1;
    EXPECT_GT(sizeOf(0), 2 * sizeOf(39)) << "the near lamp's map is not larger";
}

TEST_F(ClusteredLightsTest, ALampOutOfViewKeepsItsMapForWhenItComesBack) {
    Street street = lampGrid(40, {{"resolution", 256}});
    for (engine::Light& light : street.scene.lights) light.range = 6.0;  // a lamp lights its pool only
    engine::Renderer renderer({}, plugins());
    renderer.setScene(street.scene);
    engine::FrameRequest whole;
    whole.camera = topCamera();
    // x from -17 to -8: a lamp whose reach (6 around it) starts past -8, foot x 2 and more
    // (columns 4 to 7, 20 lamps), lights nothing seen. The lamps in view may draw their maps
    // again: their fit and size follow what the camera sees.
    engine::FrameRequest left = whole;
    left.camera.projection = glm::ortho(-17.0, -8.0, -17.0, 17.0, 0.1, 100.0);
    const auto outOfView = [](int slot) { return footOf(slot).x > -2.0; };
    const auto pluginStats = [&](const engine::FrameRequest& request) {
        return renderer.renderFrame(request).pluginStats.at("shadowmap_plugin");
    };
    EXPECT_EQ(pluginStats(whole).at("atlas").at("rendered"), 40);
    const nlohmann::json away = pluginStats(left);
    EXPECT_EQ(away.at("atlas").at("maps"), 40) << "the lamps out of view lost their place in the atlas";
    int skipped = 0;
    for (int slot = 0; slot < 40; ++slot)
        if (outOfView(slot)) {
            EXPECT_EQ(away.at("lights").at(slot).at("map"), "none") << "lamp_" << slot + 1 << " was planned";
            ++skipped;
        }
    EXPECT_EQ(skipped, 20);
    const nlohmann::json back = pluginStats(whole);
    for (int slot = 0; slot < 40; ++slot)
        if (outOfView(slot)) EXPECT_EQ(back.at("lights").at(slot).at("cache"), "hit") << "lamp_" << slot + 1;
}

TEST_F(ClusteredLightsTest, AWalkingCameraCompilesNothingAfterTheFirstFrame) {
    // The clustered pass's program does not depend on which lights a frame sees: after the
    // first frame, a camera walking across the grid (new lamps in and out of view every
    // step) links no program.
    const Street street = lampGrid(40, {{"resolution", 256}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(street.scene);
    engine::FrameRequest request;
    request.camera = engine::test::cameraLooking({-16, 3, -16}, {0, 0, 0}, 320, 180);
    (void)renderer.renderFrame(request);
    for (int step = 1; step <= 8; ++step) {
        const glm::dvec3 eye(-16.0 + 4.0 * step, 3.0, -16.0 + 3.0 * step);
        request.camera = engine::test::cameraLooking(eye, eye + glm::dvec3(1.0, -0.3, 0.4 * (step % 3 - 1)), 320, 180);
        EXPECT_EQ(renderer.renderFrame(request).programsLinked, 0) << "step " << step;
    }
}
