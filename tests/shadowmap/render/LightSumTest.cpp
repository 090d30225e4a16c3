// RendererConfig::unrolledLightSum: the lit shader's loop over the lights (the switch off,
// for measuring on GPUs) shades exactly like the term-by-term sum llvmpipe runs by default,
// with a shadowed light of every type.
//
// Tolerance: 1/255 per channel. Both programs add the same terms in the same order from the
// same inputs; only the compiler's scheduling of float operations may differ, which moves a
// value by a few ulps, less than one 8-bit step (measured: 0/255 on llvmpipe). A loop that
// skipped or repeated a light moves lit pixels by far more (the loop stopping one light
// short: 203/255, measured).
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <cstdlib>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

class LightSumTest : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }

    static std::vector<std::uint8_t> render(const engine::Scene& scene, bool unrolled) {
        engine::RendererConfig config;
        config.unrolledLightSum = unrolled;
        engine::Renderer renderer(config, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = engine::test::cameraLooking({0, 12, 10}, {0, 0, 0}, 96, 72);
        renderer.renderFrame(request);
        return renderer.readColor();
    }
};

} // namespace

TEST_F(LightSumTest, TheLoopShadesLikeTheUnrolledSum) {
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
    builder.addLight("spot", Light::Type::Spot, {-3, 8, -2}, {0, 0, 0});
    builder.addLight("bulb", Light::Type::Point, {1, 4, 2}, {1, 0, 2});
    builder.addLight("sun", Light::Type::Directional, {4, 9, -3}, {0, 0, 0});
    const engine::Scene scene = builder.build();

    const std::vector<std::uint8_t> unrolled = render(scene, true);
    const std::vector<std::uint8_t> loop = render(scene, false);
    ASSERT_EQ(unrolled.size(), loop.size());
    int maxDifference = 0, lit = 0;
    for (std::size_t i = 0; i < unrolled.size(); ++i) {
        maxDifference = std::max(maxDifference, std::abs(int(unrolled[i]) - int(loop[i])));
        lit += unrolled[i] > 16 ? 1 : 0;
    }
    EXPECT_LE(maxDifference, 1);
    EXPECT_GT(lit, int(unrolled.size() / 4)) << "the image is mostly dark: the comparison proves nothing";
}
