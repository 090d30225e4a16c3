// Settings changes do not accumulate GL objects: a few hundred frames that change every
// light's variant, map resolution and depth format and the output size every 10 frames keep
// the live textures, framebuffers, buffers and programs (LiveObjects.h) under the peak of the
// first 100 frames. Each change uses a map resolution never used before, so a pool or cache
// that keeps what it once made grows with every change (the render-graph pool did: one woo
// first layer per light and resolution, and their framebuffers, forever).
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/gl/LiveObjects.h"

#include <algorithm>
#include <array>

namespace {

using engine::Light;
using engine::gl::LiveObjectCounts;
using engine::test::SceneBuilder;

class LiveGlObjectsTest : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 64}}); }
};

LiveObjectCounts maxOf(const LiveObjectCounts& a, const LiveObjectCounts& b) {
    return {std::max(a.textures, b.textures),         std::max(a.framebuffers, b.framebuffers),
            std::max(a.buffers, b.buffers),           std::max(a.programs, b.programs),
            std::max(a.shaders, b.shaders),           std::max(a.samplers, b.samplers),
            std::max(a.vertexArrays, b.vertexArrays), std::max(a.queries, b.queries)};
}

} // namespace

TEST_F(LiveGlObjectsTest, SettingsChangesKeepTheLiveObjectCountBounded) {
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
    builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0}, {{"variant", "woo"}});
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2}, {{"variant", "woo"}});
    engine::Scene scene = builder.build();
    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);

    // Every (variant, depth format) pair within the first 9 changes (90 frames): the warm-up
    // window (100 frames) makes each program and per-variant object once, so later windows
    // differ from it only in what a leak adds.
    const std::array<const char*, 3> variants{"woo", "standard", "backface"};
    const std::array<const char*, 3> formats{"d24", "d16", "d32f"};
    const std::array<std::array<int, 2>, 3> sizes{{{96, 72}, {80, 60}, {64, 48}}};
    constexpr int kFrames = 300, kFramesPerChange = 10, kWarmUpFrames = 100;

    engine::FrameRequest request;
    LiveObjectCounts warmUpPeak, laterPeak;
    for (int frame = 0; frame < kFrames; ++frame) {
        if (frame % kFramesPerChange == 0) {
            const int change = frame / kFramesPerChange;
            for (Light& light : scene.lights)
                light.extras["shadow"] = {{"variant", variants[change % 3]},
                                          {"depth_format", formats[(change / 3) % 3]},
                                          {"resolution", 64 + 8 * change}};  // never the same twice
            renderer.reloadSettings();
            const auto [width, height] = sizes[change % 3];
            request.camera = engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, width, height);
        }
        renderer.renderFrame(request);
        LiveObjectCounts& peak = frame < kWarmUpFrames ? warmUpPeak : laterPeak;
        peak = maxOf(peak, engine::gl::liveObjectCounts());
    }
    // No tolerance: after the warm-up, the same kinds of change recur, each freeing what the
    // one before made; any object kept from an old setting adds up over the 20 later changes.
    EXPECT_LE(laterPeak.textures, warmUpPeak.textures);
    EXPECT_LE(laterPeak.framebuffers, warmUpPeak.framebuffers);
    EXPECT_LE(laterPeak.buffers, warmUpPeak.buffers);
    EXPECT_LE(laterPeak.programs, warmUpPeak.programs);
    EXPECT_LE(laterPeak.total(), warmUpPeak.total());
}
