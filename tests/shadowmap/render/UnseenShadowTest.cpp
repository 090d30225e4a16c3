// Receiver-aware caster culling through the plugin (technique/UnseenShadows.h): a caster
// whose shadow falls where the camera cannot see is left out of the depth pass, and the
// image does not change; a map drawn without it is drawn again once the camera looks where
// its shadow falls, and serves every view after that.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

// Two boxes 2 above a wide floor, one each side of a light 10 above the origin: their
// shadows fall at |x| from about 5.7 to 8.8. The camera looks at the left one's; with its
// far plane at 12 it sees nothing right of x = 0.
struct TwoShadows {
    engine::Scene scene;
    static constexpr int kLeftBox = 1, kRightBox = 2;

    TwoShadows(Light::Type type, const nlohmann::json& shadow) {
        SceneBuilder builder;
        builder.addBox("floor", {-20, -0.2, -20}, {20, 0, 20});
        builder.addBox("left_box", {-7, 2, -1}, {-5, 3, 1});
        builder.addBox("right_box", {5, 2, -1}, {7, 3, 1});
        builder.addLight("light", type, {0, 10, 0.01}, {0, 0, 0}, shadow, 1.2);
        scene = builder.build();
    }
};

engine::FrameCamera lookingAt(double x) {
    engine::FrameCamera camera = engine::test::cameraLooking({x, 5, 5}, {x, 0, 0}, 64, 48);
    camera.projection = glm::perspective(0.9, 64.0 / 48.0, 0.1, 12.0);
    return camera;
}

class UnseenShadow : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }

    // One light's mask from a renderer kept across calls, and what the plugin counted.
    struct Shot {
        std::vector<std::uint8_t> mask;
        nlohmann::json light;  // the light's --stats entry
        bool mapRendered = false;
    };
    static Shot shoot(engine::Renderer& renderer, const engine::FrameCamera& camera) {
        engine::FrameRequest request;
        request.camera = camera;
        request.shadowMaskSlots = {0};
        const engine::FrameResult result = renderer.renderFrame(request);
        Shot shot;
        shot.mask = renderer.readShadowMask(0);
        shot.light = plugins()[0]->frameStats()["lights"][0];
        shot.mapRendered = result.shadowView(0)->renderedThisFrame;
        return shot;
    }
    static Shot shootOnce(const engine::Scene& scene, const engine::FrameCamera& camera) {
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        return shoot(renderer, camera);
    }
};

int darkPixels(const std::vector<std::uint8_t>& mask) {
    return static_cast<int>(std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v < 128; }));
}

struct Case {
    const char* name;
    Light::Type type;
    const char* variant;
    int leftOut;  // casters the light's views leave out
};

class UnseenShadowCases : public UnseenShadow, public ::testing::WithParamInterface<Case> {};

TEST_P(UnseenShadowCases, TheCasterWhoseShadowIsOffScreenIsLeftOutAndTheMaskIsTheSame) {
    const Case& c = GetParam();
    const TwoShadows culled(c.type, {{"variant", c.variant}});
    const TwoShadows kept(c.type, {{"variant", c.variant}, {"cull_unseen_casters", false}});
    const Shot withCulling = shootOnce(culled.scene, lookingAt(-6));
    const Shot without = shootOnce(kept.scene, lookingAt(-6));
    // The left box's shadow is in view (else the comparison shows nothing).
    EXPECT_GT(darkPixels(withCulling.mask), 100);
    EXPECT_EQ(withCulling.mask, without.mask);
    EXPECT_EQ(withCulling.light["casters_unseen"], c.leftOut);
    EXPECT_EQ(without.light["casters_unseen"], 0);
    if (c.leftOut > 0) EXPECT_LT(withCulling.light["draws"].get<int>(), without.light["draws"].get<int>());
    else EXPECT_EQ(withCulling.light["draws"], without.light["draws"]);
}

// The right box, once: for the point light only the downward cube face holds it (it lies
// 7 to 8 below the light and at most 7 to the side). The floor, a visible receiver that also
// casts, stays. Woo keeps every caster.
INSTANTIATE_TEST_SUITE_P(Lights, UnseenShadowCases,
                         ::testing::Values(Case{"spot", Light::Type::Spot, "standard", 1},
                                           Case{"spot_backface", Light::Type::Spot, "backface", 1},
                                           Case{"spot_woo", Light::Type::Spot, "woo", 0},
                                           Case{"point", Light::Type::Point, "standard", 1}),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST_F(UnseenShadow, AMapDrawnWithoutACasterIsDrawnAgainWhenItsShadowComesIntoView) {
    const TwoShadows world(Light::Type::Spot, {{"variant", "standard"}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(world.scene);
    const Shot left = shoot(renderer, lookingAt(-6));
    EXPECT_TRUE(left.mapRendered);
    EXPECT_EQ(left.light["casters_unseen"], 1);
    // The camera turns to the right box's shadow: the map lacks that box, so it is drawn
    // again, and the mask is the one a renderer that never culled gives.
    const Shot right = shoot(renderer, lookingAt(6));
    EXPECT_TRUE(right.mapRendered);
    const TwoShadows kept(Light::Type::Spot, {{"variant", "standard"}, {"cull_unseen_casters", false}});
    const Shot fresh = shootOnce(kept.scene, lookingAt(6));
    EXPECT_GT(darkPixels(fresh.mask), 100);
    EXPECT_EQ(right.mask, fresh.mask);
    // Back to the left: the map now holds both boxes and serves as it is.
    const Shot back = shoot(renderer, lookingAt(-6));
    EXPECT_FALSE(back.mapRendered);
    EXPECT_EQ(back.mask, left.mask);
}

TEST_F(UnseenShadow, AMapKeptAcrossReloadedSettingsStillKnowsTheCasterItLacks) {
    // Reloading the settings keeps a light's map (its key covers the settings); it must keep
    // the record of the caster left out of it too, or the turn to its shadow would be a hit.
    const TwoShadows world(Light::Type::Spot, {{"variant", "standard"}});
    engine::Renderer renderer({}, plugins());
    renderer.setScene(world.scene);
    EXPECT_EQ(shoot(renderer, lookingAt(-6)).light["casters_unseen"], 1);
    renderer.reloadSettings();
    const Shot right = shoot(renderer, lookingAt(6));
    EXPECT_TRUE(right.mapRendered);
    const TwoShadows kept(Light::Type::Spot, {{"variant", "standard"}, {"cull_unseen_casters", false}});
    EXPECT_EQ(right.mask, shootOnce(kept.scene, lookingAt(6)).mask);
}

} // namespace
