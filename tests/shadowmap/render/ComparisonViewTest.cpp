// The comparison view (engine-render --shadow-compare) judges what the lookup judges: where
// it paints "reference behind the stored depth" (red) the light's one-tap shade is 0, where
// it paints "in front" (blue) the shade is 1. For a point light the view compares the cube
// lookup's own biased depth (cubeBiasedReference). The cube's texel bias is, in window depth,
// far below the view's 1e-3 agreement band here, so this scene passes with the unbiased
// reference too; swapping the view's two depths fails it (14380 red pixels lit).
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

namespace {

using engine::Light;
using engine::test::SceneBuilder;

class ComparisonView : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}, {"filter", "nearest"}}); }
};

} // namespace

TEST_F(ComparisonView, PointLightViewAgreesWithItsMask) {
    SceneBuilder builder;
    builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
    builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
    builder.addLight("bulb", Light::Type::Point, {2, 3, 1}, {0, 0, 0});
    const engine::Scene scene = builder.build();
    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = engine::test::cameraLooking({0, 9, 9}, {0, 0, 0}, 160, 120);
    request.shadowMaskSlots = {0};
    request.comparisonSlots = {0};
    renderer.renderFrame(request);
    const std::vector<std::uint8_t> mask = renderer.readShadowMask(0);
    const std::vector<std::uint8_t> view = renderer.readComparison(0);
    ASSERT_EQ(view.size(), mask.size() * 4);
    // Colours of visibility.glsl's comparisonColor: red (0.85, 0.1, 0.1), blue (0.1, 0.2, 0.9).
    int red = 0, blue = 0, redButLit = 0, blueButShadowed = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const std::uint8_t* c = &view[4 * i];
        if (c[0] > 180 && c[1] < 60 && c[2] < 60) {
            ++red;
            redButLit += mask[i] != 0;
        } else if (c[2] > 180 && c[0] < 60) {
            ++blue;
            blueButShadowed += mask[i] != 255;
        }
    }
    EXPECT_EQ(redButLit, 0);
    EXPECT_EQ(blueButShadowed, 0);
    EXPECT_GT(red, 100) << "no shadow in view: the check proves nothing";
    EXPECT_GT(blue, 100);
}
