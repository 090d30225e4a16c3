// The lit pass's shade cache (engine/render/ShadeCache.h) with the shadow plugin's shade
// keys: which lights a frame reuses and which it recomputes (from FrameResult::shadeCache),
// and that reused shade never goes stale: every frame's image equals the image of a
// renderer that caches neither maps nor shade.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/scene/SceneEdit.h"

#include <algorithm>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

// Whether a pass that ran this frame read a light's shadow map (the maps as the plugin's
// shadow views name them). (The lit pass also reads the shade cache, an input of another kind.)
bool aPassReadsAShadowMap(const engine::FrameResult& frame) {
    for (const engine::PassReport& pass : frame.passes)
        for (const engine::ShadowView& view : frame.shadowViews)
            if (!pass.culled && view.hasMap &&
                std::find(pass.reads.begin(), pass.reads.end(), view.map) != pass.reads.end())
                return true;
    return false;
}

class ShadeCacheTest : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }

    struct Lit {
        SceneBuilder builder;
        int spot = -1, bulb = -1;  // nodes
    };
    // A box over a floor, a shadowed spot (slot 0), a shadowed point light (slot 1) and a
    // spot without shadows (slot 2, variant none: no map, nothing to cache).
    static Lit boxTwoShadowedLightsAndOneWithout() {
        Lit lit;
        lit.builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
        lit.builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
        lit.spot = lit.builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
        lit.bulb = lit.builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});
        lit.builder.addLight("plain", Light::Type::Spot, {3, 6, 3}, {0, 0, 0}, {{"variant", "none"}});
        return lit;
    }
    static engine::FrameCamera camera() { return engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, 96, 72); }

    // A renderer with the plugin over a scene, and the test camera.
    struct Session {
        engine::Scene scene;
        engine::Renderer renderer;
        engine::FrameRequest request;
        explicit Session(engine::Scene built, const engine::RendererConfig& config = {})
            : scene(std::move(built)), renderer(config, plugins()) {
            renderer.setScene(scene);
            request.camera = camera();
        }
        engine::FrameResult frame() { return renderer.renderFrame(request); }
    };
};

} // namespace

TEST_F(ShadeCacheTest, AStaticSceneComputesEachShadeOnceThenFetchesIt) {
    Session session(boxTwoShadowedLightsAndOneWithout().builder.build());
    const engine::FrameResult first = session.frame();
    EXPECT_EQ(first.shadeCache.layers, 1);
    EXPECT_EQ(first.shadeCache.computed, (std::vector<int>{0, 1}));
    EXPECT_EQ(first.shadeCache.constant, (std::vector<int>{2}));  // variant none: shade 1
    EXPECT_TRUE(aPassReadsAShadowMap(first)) << first.graphviz;
    for (int frame = 1; frame < 4; ++frame) {
        const engine::FrameResult later = session.frame();
        EXPECT_EQ(later.shadeCache.fetched, (std::vector<int>{0, 1})) << "frame " << frame;
        EXPECT_TRUE(later.shadeCache.computed.empty()) << "frame " << frame;
        // Every shade reused: the lit pass reads no shadow map (frame 0's reads both).
        EXPECT_FALSE(aPassReadsAShadowMap(later)) << later.graphviz;
    }
}

// Renderer::warmUp for timing tools: the first frame compiles the programs that compute
// the lights' shade, the second the ones that fetch it from the cache (a plan of its own),
// the third compiles nothing and ends warm-up; a frame after it compiles nothing either, so
// no timed frame pays for compilation. One warm-up frame (what engine-render did before)
// left the fetching programs to the first timed frame.
TEST_F(ShadeCacheTest, WarmUpRendersUntilAFrameCompilesNothingNew) {
    Session session(boxTwoShadowedLightsAndOneWithout().builder.build());
    EXPECT_EQ(session.renderer.warmUp(session.request, 1, 10), 3);
    EXPECT_EQ(session.renderer.warmUp(session.request, 1, 10), 1);
    EXPECT_EQ(session.frame().shadeCache.fetched, (std::vector<int>{0, 1}));
    // At least minFrames, at most maxFrames, whatever compiles.
    Session bounded(boxTwoShadowedLightsAndOneWithout().builder.build());
    EXPECT_EQ(bounded.renderer.warmUp(bounded.request, 1, 2), 2);
    EXPECT_EQ(bounded.renderer.warmUp(bounded.request, 3, 10), 3);
}

TEST_F(ShadeCacheTest, MovingOneLightRecomputesOnlyItsShade) {
    Lit lit = boxTwoShadowedLightsAndOneWithout();
    Session session(lit.builder.build());
    session.frame();
    // Moved once: recomputed and stored, the other light fetched.
    engine::orbitNode(session.scene, lit.spot, {0, 0, 0}, 0.1);
    engine::FrameResult result = session.frame();
    EXPECT_EQ(result.shadeCache.computed, (std::vector<int>{0}));
    EXPECT_EQ(result.shadeCache.fetched, (std::vector<int>{1}));
    // Moved again, and again: moving, recomputed without storing; the frame writes no cache
    // array at all (nothing is computed), the other light is still fetched.
    for (int frame = 2; frame < 4; ++frame) {
        engine::orbitNode(session.scene, lit.spot, {0, 0, 0}, 0.1);
        result = session.frame();
        EXPECT_EQ(result.shadeCache.moving, (std::vector<int>{0})) << "frame " << frame;
        EXPECT_TRUE(result.shadeCache.computed.empty()) << "frame " << frame;
        EXPECT_EQ(result.shadeCache.fetched, (std::vector<int>{1})) << "frame " << frame;
    }
    // Stopped: stored on its first still frame, fetched from then on.
    result = session.frame();
    EXPECT_EQ(result.shadeCache.computed, (std::vector<int>{0}));
    EXPECT_TRUE(result.shadeCache.moving.empty());
    EXPECT_EQ(session.frame().shadeCache.fetched, (std::vector<int>{0, 1}));
}

TEST_F(ShadeCacheTest, AMovingLightIsStoredWhenAnotherLightWritesTheCache) {
    // The spot keeps moving while the bulb changes once: the frame that recomputes the bulb
    // writes the array, and with it the spot's shade for that frame; the spot stopping
    // then costs nothing.
    Lit lit = boxTwoShadowedLightsAndOneWithout();
    Session session(lit.builder.build());
    session.frame();
    for (int frame = 1; frame < 3; ++frame) {
        engine::orbitNode(session.scene, lit.spot, {0, 0, 0}, 0.1);
        session.frame();
    }
    engine::orbitNode(session.scene, lit.spot, {0, 0, 0}, 0.1);
    engine::orbitNode(session.scene, lit.bulb, {0, 0, 0}, 0.1);
    const engine::FrameResult both = session.frame();
    EXPECT_EQ(both.shadeCache.moving, (std::vector<int>{0}));
    EXPECT_EQ(both.shadeCache.computed, (std::vector<int>{1}));
    EXPECT_EQ(session.frame().shadeCache.fetched, (std::vector<int>{0, 1}));
}

TEST_F(ShadeCacheTest, MovingTheCameraOrAnyMeshRecomputesEveryShade) {
    Lit lit = boxTwoShadowedLightsAndOneWithout();
    const int farAway = lit.builder.addBox("far_away", {40, 0, 40}, {41, 1, 41});
    Session session(lit.builder.build());
    session.frame();

    session.request.camera.eyeToWorld = engine::orbitTransform(session.request.camera.eyeToWorld, {0, 0, 0}, 0.05);
    EXPECT_EQ(session.frame().shadeCache.computed, (std::vector<int>{0, 1}));
    EXPECT_EQ(session.frame().shadeCache.fetched, (std::vector<int>{0, 1}));

    // A mesh no light and no camera sees still counts: the key covers every surface the
    // lit pass may draw, so nothing visible can have changed without a recompute.
    session.scene.nodes[farAway].local[3].x += 1.0;
    session.scene.updateWorldTransforms();
    EXPECT_EQ(session.frame().shadeCache.computed, (std::vector<int>{0, 1}));

    // Two changes in a row (the mesh above, the camera now): every light is moving.
    session.request.camera.eyeToWorld = engine::orbitTransform(session.request.camera.eyeToWorld, {0, 0, 0}, 0.05);
    EXPECT_EQ(session.frame().shadeCache.moving, (std::vector<int>{0, 1}));
    EXPECT_EQ(session.frame().shadeCache.computed, (std::vector<int>{0, 1}));

    // So does a new target size (the cache arrays are recreated at it).
    session.request.camera.width = 80;
    session.request.camera.height = 60;
    EXPECT_EQ(session.frame().shadeCache.computed, (std::vector<int>{0, 1}));
    EXPECT_EQ(session.frame().shadeCache.fetched, (std::vector<int>{0, 1}));

    // A new scene forgets everything.
    session.renderer.setScene(session.scene);
    EXPECT_EQ(session.frame().shadeCache.computed, (std::vector<int>{0, 1}));
}

TEST_F(ShadeCacheTest, ShadeCacheOffOrNoShadowedLightMeansNoCache) {
    engine::RendererConfig config;
    config.shadeCache = false;
    Session session(boxTwoShadowedLightsAndOneWithout().builder.build(), config);
    session.frame();
    const engine::FrameResult off = session.frame();
    EXPECT_EQ(off.shadeCache.layers, 0);
    EXPECT_EQ(off.shadeCache.uncached, (std::vector<int>{0, 1, 2}));

    SceneBuilder unshadowed;
    unshadowed.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    unshadowed.addLight("plain", Light::Type::Spot, {3, 6, 3}, {0, 0, 0}, {{"variant", "none"}});
    Session plain(unshadowed.build());
    EXPECT_EQ(plain.frame().shadeCache.layers, 0);
}

TEST_F(ShadeCacheTest, ReusedShadeGivesTheImageOfAFreshFrame) {
    // Five shadowed lights (two cache layers) and two constant ones; a light moves for two
    // frames (the second time it is moving: evaluated, not stored), the camera and a caster
    // move and stop, and the target size changes. After every change and
    // every still frame the image equals that of a renderer that caches neither maps nor
    // shade. Shade is cached as exact floats, so the images are compared exactly.
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    const int box = builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
    builder.addBox("pillar", {2, 0, -3}, {2.5, 3, -2.5});
    const int spot = builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});
    builder.addLight("sun", Light::Type::Directional, {4, 9, 3}, {0, 0, 0});
    builder.addLight("spot2", Light::Type::Spot, {5, 7, -4}, {0, 0, 0}, {{"filter", "nearest"}});
    builder.addLight("bulb2", Light::Type::Point, {-3, 3, 3}, {0, 0, 0}, {{"variant", "backface"}});
    // Two lights with one shade everywhere: no shadows (1), and a spot facing the sky,
    // whose frustum holds nothing the camera sees (0).
    builder.addLight("plain", Light::Type::Spot, {3, 6, 3}, {0, 0, 0}, {{"variant", "none"}});
    builder.addLight("skyward", Light::Type::Spot, {0, 5, 0}, {0, 10, 0});
    engine::Scene scene = builder.build();

    engine::PluginHost freshHost;
    freshHost.load({"shadowmap_plugin", {{"resolution", 256}, {"cache_maps", false}}}, {ENGINE_PLUGIN_DIR});
    engine::RendererConfig noCache;
    noCache.shadeCache = false;
    engine::Renderer cached({}, plugins()), fresh(noCache, freshHost.renderPlugins());
    cached.setScene(scene);
    fresh.setScene(scene);
    engine::FrameRequest request;
    request.camera = camera();
    int fetchedFrames = 0;
    for (int frame = 0; frame < 11; ++frame) {
        if (frame == 2 || frame == 3) engine::orbitNode(scene, spot, {0, 0, 0}, 0.3);
        if (frame == 4) request.camera.eyeToWorld = engine::orbitTransform(request.camera.eyeToWorld, {0, 0, 0}, 0.2);
        if (frame == 6) {
            scene.nodes[box].local[3].x += 0.5;
            scene.updateWorldTransforms();
        }
        if (frame == 9) {
            request.camera.width = 80;
            request.camera.height = 60;
        }
        const engine::FrameResult result = cached.renderFrame(request);
        fresh.renderFrame(request);
        EXPECT_EQ(result.shadeCache.layers, 2);
        EXPECT_EQ(result.shadeCache.constant, (std::vector<int>{5, 6}));
        fetchedFrames += !result.shadeCache.fetched.empty();
        if (frame == 3) {
            EXPECT_EQ(result.shadeCache.moving, (std::vector<int>{0}));
        }
        const std::vector<std::uint8_t> image = cached.readColor(), expected = fresh.readColor();
        ASSERT_EQ(image.size(), expected.size());
        int differing = 0;
        for (std::size_t i = 0; i < image.size(); ++i) differing += image[i] != expected[i];
        EXPECT_EQ(differing, 0) << "frame " << frame;
    }
    // Frames 0, 4 (camera), 6 (caster) and 9 (size) recompute everything; 2 and 3 only
    // the spot.
    EXPECT_EQ(fetchedFrames, 7);
}

TEST_F(ShadeCacheTest, WithoutMapCachingEveryFrameRendersEveryMapAndShade) {
    // cache_maps false is how the bench and the showcase time the passes: no map and no
    // shade may be reused, or a depth pass nobody reads would be culled and time nothing.
    engine::PluginHost host;
    host.load({"shadowmap_plugin", {{"resolution", 256}, {"cache_maps", false}}}, {ENGINE_PLUGIN_DIR});
    engine::Scene scene = boxTwoShadowedLightsAndOneWithout().builder.build();
    engine::Renderer renderer({}, host.renderPlugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = camera();
    for (int frame = 0; frame < 3; ++frame) {
        const engine::FrameResult result = renderer.renderFrame(request);
        EXPECT_EQ(result.shadeCache.uncached, (std::vector<int>{0, 1})) << "frame " << frame;
        EXPECT_EQ(result.shadeCache.constant, (std::vector<int>{2})) << "frame " << frame;
        for (const int slot : {0, 1}) {  // spot and bulb: their maps re-rendered every frame
            bool ran = false;
            ASSERT_TRUE(result.shadowView(slot));
            result.shadowPassMs(*result.shadowView(slot), ran);
            EXPECT_TRUE(ran) << "slot " << slot << ", frame " << frame;
        }
    }
}
