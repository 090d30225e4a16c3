// Work the plugin and the renderer must skip: cached maps, lights and faces that light no
// visible receiver, draws outside the light's or the camera's frustum. Checked through the
// frame graph's reports and the lights' shadow views, over several frames.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/scene/SceneEdit.h"
#include "shadowmap/ShadowViewSettings.h"

#include <algorithm>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

struct Frames {
    std::vector<engine::FrameResult> results;

    // How many frames ran the shadow passes of light `name` (its shadow view's passes).
    int mapRenders(const std::string& name) const {
        int runs = 0;
        for (const auto& frame : results)
            for (const engine::ShadowView& view : frame.shadowViews) {
                bool ran = false;
                if (view.name == name) frame.shadowPassMs(view, ran);
                runs += ran;
            }
        return runs;
    }
    // How many maps, summed over frames, were served from the cache.
    int cacheHits() const {
        int hits = 0;
        for (const auto& frame : results)
            for (const engine::ShadowView& view : frame.shadowViews) hits += view.hasMap && !view.renderedThisFrame;
        return hits;
    }
    const engine::ShadowView& lastLight(int slot) const { return *results.back().shadowView(slot); }
};

class SkipWork : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }

    // Renders `count` frames, calling `change(frame)` before each frame after the first.
    template <typename Change>
    Frames render(engine::Scene& scene, int count, Change change,
                  engine::FrameCamera camera = engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, 64, 48)) {
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        Frames frames;
        for (int frame = 0; frame < count; ++frame) {
            if (frame > 0) change(frame);
            engine::FrameRequest request;
            request.camera = camera;
            frames.results.push_back(renderer.renderFrame(request));
        }
        return frames;
    }
};

SceneBuilder boxOverFloor() {
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
    return builder;
}

} // namespace

TEST_F(SkipWork, StaticSceneRendersEachMapOnce) {
    SceneBuilder builder = boxOverFloor();
    builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
    builder.addLight("sun", Light::Type::Directional, {4, 9, 3}, {0, 0, 0});
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 5, [](int) {});
    EXPECT_EQ(frames.mapRenders("spot"), 1);
    EXPECT_EQ(frames.mapRenders("sun"), 1);
    EXPECT_EQ(frames.mapRenders("bulb"), 1);
    EXPECT_EQ(frames.cacheHits(), 12);  // three lights in four frames after the first
    EXPECT_FALSE(frames.lastLight(0).renderedThisFrame);
}

TEST_F(SkipWork, MovingALightRerendersOnlyItsMap) {
    SceneBuilder builder = boxOverFloor();
    builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
    const int sun = builder.addLight("sun", Light::Type::Directional, {4, 9, 3}, {0, 0, 0});
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 4, [&](int) { engine::orbitNode(scene, sun, {0, 0, 0}, 0.05); });
    EXPECT_EQ(frames.mapRenders("spot"), 1);
    EXPECT_EQ(frames.mapRenders("sun"), 4);
}

TEST_F(SkipWork, MovingACasterOutsideTheFrustumKeepsTheMapMovingOneInsideDoesNot) {
    SceneBuilder builder = boxOverFloor();
    const int far = builder.addBox("far_box", {30, 0, 30}, {31, 1, 31});  // outside the cone
    builder.addLight("spot", Light::Type::Spot, {0, 8, 0}, {0, 0, 0}, {}, 0.5);
    engine::Scene scene = builder.build();
    const auto moveFar = [&](int) {
        scene.nodes[far].local[3].x += 1.0;
        scene.updateWorldTransforms();
    };
    EXPECT_EQ(render(scene, 3, moveFar).mapRenders("spot"), 1);

    const int box = 1;  // the box under the light
    const auto moveBox = [&](int) {
        scene.nodes[box].local[3].x += 0.1;
        scene.updateWorldTransforms();
    };
    EXPECT_EQ(render(scene, 3, moveBox).mapRenders("spot"), 3);
}

TEST_F(SkipWork, LightsThatCastNoShadowAddNoPass) {
    SceneBuilder builder = boxOverFloor();
    builder.addLight("off", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0}, {{"variant", "none"}});
    const int dark = builder.addLight("dark", Light::Type::Spot, {3, 8, 2}, {0, 0, 0});
    builder.addLight("away", Light::Type::Spot, {0, 8, 0}, {0, 20, 0});  // sees no receiver
    builder.scene.lights[builder.scene.nodes[dark].light].intensity = 0.0f;
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 1, [](int) {});
    for (const char* light : {"off", "dark", "away"})
        EXPECT_EQ(frames.mapRenders(light), 0) << light;
    EXPECT_EQ(frames.lastLight(0).skipReason, "variant none");
    EXPECT_EQ(frames.lastLight(1).skipReason, "the light emits nothing");
    EXPECT_EQ(frames.lastLight(2).skipReason, "no visible receiver in the light's frustum");
}

TEST_F(SkipWork, PointLightSkipsFacesThatSeeNoReceiver) {
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    builder.addLight("bulb", Light::Type::Point, {0, 3, 0}, {0, 0, 0});
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 1, [](int) {});
    const engine::ShadowView& light = frames.lastLight(0);
    ASSERT_EQ(light.layers.size(), 6u);
    const auto skipped = std::count_if(light.layers.begin(), light.layers.end(),
                                       [](const engine::ShadowMapLayer& face) { return !face.rendered; });
    EXPECT_GE(skipped, 1);  // +Y looks at nothing
    EXPECT_LT(skipped, 6);  // the faces looking down see the floor
}

TEST_F(SkipWork, CastersOutsideTheLightAndMeshesOutsideTheViewAreNotDrawn) {
    SceneBuilder builder = boxOverFloor();
    builder.addBox("far_box", {30, 0, 30}, {31, 1, 31});
    builder.addLight("spot", Light::Type::Spot, {0, 8, 0}, {0, 0, 0}, {}, 0.5);
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 1, [](int) {});
    const engine::FrameResult::PassWork spot = frames.results.back().shadowPassWork(frames.lastLight(0));
    EXPECT_EQ(spot.drawsCulled, 1u);  // far_box is outside the cone
    EXPECT_EQ(spot.draws, 2u);        // floor and box
    EXPECT_EQ(frames.results.back().litInstancesCulled, 1);  // far_box is outside the view
}

TEST_F(SkipWork, MovingACasterInvalidatesExactlyTheLightsThatSeeIt) {
    // Two narrow spots, one over each half of the floor; the box under the left one moves.
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    const int left = builder.addBox("left_box", {-5.5, 1, -0.5}, {-4.5, 2, 0.5});
    builder.addBox("right_box", {4.5, 1, -0.5}, {5.5, 2, 0.5});
    builder.addLight("left_spot", Light::Type::Spot, {-5, 8, 0}, {-5, 0, 0}, {}, 0.35);
    builder.addLight("right_spot", Light::Type::Spot, {5, 8, 0}, {5, 0, 0}, {}, 0.35);
    engine::Scene scene = builder.build();
    const Frames frames = render(scene, 4, [&](int) {
        scene.nodes[left].local[3].z += 0.05;
        scene.updateWorldTransforms();
    });
    EXPECT_EQ(frames.mapRenders("left_spot"), 4);
    EXPECT_EQ(frames.mapRenders("right_spot"), 1);
}

TEST_F(SkipWork, CachedMapsGiveTheSameMasksAsFreshOnes) {
    // Cached output must never go stale: after the light has moved and come back, and the
    // camera has moved, the masks equal those of a renderer that caches nothing.
    SceneBuilder builder = boxOverFloor();
    const int spot = builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});
    engine::Scene scene = builder.build();
    const engine::FrameCamera camera = engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, 96, 72);

    engine::PluginHost uncachedHost;
    uncachedHost.load({"shadowmap_plugin", {{"resolution", 256}, {"cache_maps", false}}}, {ENGINE_PLUGIN_DIR});
    engine::Renderer cached({}, plugins()), uncached({}, uncachedHost.renderPlugins());
    cached.setScene(scene);
    uncached.setScene(scene);
    engine::FrameRequest request;
    request.camera = camera;
    request.shadowMaskSlots = {0, 1};
    for (int frame = 0; frame < 4; ++frame) {
        // Frame 1 moves the spot away, frame 2 moves it back: the cache must miss, then hit
        // a key equal to frame 0's again, never reuse frame 1's map.
        if (frame == 1) engine::orbitNode(scene, spot, {0, 0, 0}, 0.3);
        if (frame == 2) engine::orbitNode(scene, spot, {0, 0, 0}, -0.3);
        if (frame == 3) request.camera.eyeToWorld = engine::orbitTransform(camera.eyeToWorld, {0, 0, 0}, 0.2);
        cached.renderFrame(request);
        uncached.renderFrame(request);
        for (int slot : {0, 1})
            EXPECT_EQ(cached.readShadowMask(slot), uncached.readShadowMask(slot))
                << "frame " << frame << ", light slot " << slot;
    }
}

TEST_F(SkipWork, ReloadedSettingsRerenderOnlyTheChangedLightAndMatchAFreshScene) {
    // The sweeps (shadowmap-bench, shadowmap-stress) and engine-view change settings through
    // Renderer::reloadSettings, not setScene: the plugin must re-read extras.shadow, re-render
    // the maps whose settings changed, keep the others, and give exactly the images of a
    // plugin that prepared the edited scene from scratch.
    SceneBuilder builder = boxOverFloor();
    builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});  // scene.lights[0]
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});   // scene.lights[1]
    engine::Scene scene = builder.build();

    engine::PluginHost freshHost;
    freshHost.load({"shadowmap_plugin", {{"resolution", 256}}}, {ENGINE_PLUGIN_DIR});
    engine::Renderer reloaded({}, plugins()), fresh({}, freshHost.renderPlugins());
    reloaded.setScene(scene);
    engine::FrameRequest request;
    request.camera = engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, 96, 72);
    request.shadowMaskSlots = {0, 1};
    reloaded.renderFrame(request);

    struct Edit {
        const char* what;
        nlohmann::json shadow;  // the spot's new extras.shadow
        bool spotRedrawn;       // true: the edit changes the map; false: only how it is read
        shadowmap::Filter filter;
    };
    const Edit edits[] = {
        {"resolution", {{"resolution", 128}}, true, shadowmap::Filter::Pcf},
        {"depth format and offset", {{"resolution", 128}, {"depth_format", "d32f"}, {"polygon_offset", {1.0, 4.0}}},
         true, shadowmap::Filter::Pcf},
        {"filter and dimming", {{"resolution", 128}, {"depth_format", "d32f"}, {"polygon_offset", {1.0, 4.0}},
                                {"filter", "nearest"}, {"dimming", 0.1}}, false, shadowmap::Filter::Nearest},
    };
    for (const Edit& edit : edits) {
        SCOPED_TRACE(edit.what);
        scene.lights[0].extras = {{"shadow", edit.shadow}};
        reloaded.reloadSettings();
        const engine::FrameResult frame = reloaded.renderFrame(request);
        const engine::ShadowView& spot = *frame.shadowView(0);
        EXPECT_EQ(spot.renderedThisFrame, edit.spotRedrawn);
        EXPECT_FALSE(frame.shadowView(1)->renderedThisFrame) << "the bulb's settings did not change";
        const shadowmap::ShadowSettings used = shadowmap::usedSettings(spot);
        EXPECT_EQ(used.resolution, 128);
        EXPECT_EQ(used.filter, edit.filter);

        fresh.setScene(scene);
        fresh.renderFrame(request);
        for (int slot : {0, 1}) EXPECT_EQ(reloaded.readShadowMask(slot), fresh.readShadowMask(slot)) << "slot " << slot;
        EXPECT_EQ(reloaded.readColor(), fresh.readColor()) << "dimming reaches the shaded image";
    }
}
