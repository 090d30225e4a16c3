// The ambient-retaining modulate (lit.frag), end to end through the plugin and the lit
// pass: per light, color = base + (d + (1 - d) * shade) * diffuse + shade * specular. So in
// linear color, where a light is fully shadowed (shade 0) the image moves linearly with
// the dimming d, and where it is lit (shade 1) d changes nothing. Checked for the frame
// that computes the shade and for the next one, which reads it from the shade cache.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <cmath>
#include <cstdio>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

double srgbToLinear(std::uint8_t byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

struct Rendered {
    std::vector<std::uint8_t> color;  // RGBA, sRGB encoded
    std::vector<std::uint8_t> mask;   // the spot's shade, 255 = lit
};

class Modulate : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 512}}); }

    // A box shadowing a floor under one spot light with dimming `dimming`; `frame` 0 or 1
    // (the second frame reads every shade from the cache).
    static Rendered render(double dimming, int frame) {
        SceneBuilder builder;
        builder.addBox("floor", {-10, -0.2, -10}, {10, 0, 10});
        builder.addBox("box", {-1, 1, -1}, {1, 2, 1});
        builder.addLight("spot", Light::Type::Spot, {-2, 8, -1}, {0, 0, 0}, {{"dimming", dimming}});
        engine::Scene scene = builder.build();
        scene.lights[0].intensity = 100.0f;  // a diffuse part well above 8-bit steps
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = engine::test::cameraLooking({0, 12, 8}, {0, 0, 0}, 96, 72);
        request.shadowMaskSlots = {0};
        engine::FrameResult result;
        for (int i = 0; i <= frame; ++i) result = renderer.renderFrame(request);
        EXPECT_EQ(frame == 0 ? result.shadeCache.computed : result.shadeCache.fetched, std::vector<int>{0});
        return {renderer.readColor(), renderer.readShadowMask(0)};
    }
};

} // namespace

TEST_F(Modulate, ShadowedColorIsLinearInDimmingAndLitColorIgnoresIt) {
    for (int frame : {0, 1}) {
        const Rendered none = render(0.0, frame), half = render(0.5, frame), full = render(1.0, frame);
        ASSERT_EQ(none.mask, half.mask);
        ASSERT_EQ(none.mask, full.mask);
        int shadowedChecked = 0, litChecked = 0;
        double worstShadowed = 0.0;
        int worstLit = 0;
        for (std::size_t pixel = 0; pixel < none.mask.size(); ++pixel) {
            for (int channel = 0; channel < 3; ++channel) {
                const std::size_t i = pixel * 4 + channel;
                if (none.mask[pixel] == 255) {
                    worstLit = std::max({worstLit, std::abs(none.color[i] - half.color[i]),
                                         std::abs(none.color[i] - full.color[i])});
                    ++litChecked;
                } else if (none.mask[pixel] == 0) {
                    // Only where the light's diffuse part is clearly visible.
                    const double c0 = srgbToLinear(none.color[i]), c1 = srgbToLinear(full.color[i]);
                    if (c1 - c0 < 0.05) continue;
                    const double expectedHalf = c0 + 0.5 * (c1 - c0);
                    worstShadowed = std::max(worstShadowed, std::abs(srgbToLinear(half.color[i]) - expectedHalf));
                    ++shadowedChecked;
                }
            }
        }
        // One 8-bit sRGB step is at most 0.013 in linear near these values.
        EXPECT_LE(worstShadowed, 0.01) << "frame " << frame;
        EXPECT_EQ(worstLit, 0) << "frame " << frame;
        EXPECT_GT(shadowedChecked, 100) << "frame " << frame;
        EXPECT_GT(litChecked, 1000) << "frame " << frame;
        std::printf("frame %d: %d shadowed, %d lit channel values checked; worst %.4f linear\n", frame,
                    shadowedChecked, litChecked, worstShadowed);
    }
}
