// renderer.msaa: a multisampled shaded image antialiases geometry edges and leaves the inside
// of surfaces as the single-sampled image has it; msaa 1 makes no multisampled target and no
// resolve; more samples than the GL offers is an error naming the key. Every comparison is
// between two renders of the same run: llvmpipe's rounding differs between CPUs.
#include "LitShadingFixture.h"

#include "engine/util/Error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

using namespace engine::test::lit;

// Large enough that the square's slanted edges cross a few hundred pixels.
constexpr int kImageSize = 128;
// A square of half size 0.3 turned 20 degrees about the view axis: every edge slants, so
// single-sampled it is a staircase. The camera sees about +-0.93 at its depth: the whole
// square, on the clear colour all round.
constexpr double kSquareScale = 0.15, kSquareTurn = 0.35;

engine::Scene turnedSquare() {
    engine::Scene scene = planeScene(1.0f);
    scene.nodes[0].local = glm::rotate(glm::dmat4(1.0), kSquareTurn, glm::dvec3(0, 0, 1)) *
                           glm::scale(glm::dmat4(1.0), glm::dvec3(kSquareScale));
    return scene;
}

engine::FrameCamera squareCamera() {
    engine::FrameCamera frame = camera();
    frame.width = frame.height = kImageSize;
    return frame;
}

struct Rendered {
    std::vector<std::uint8_t> rgba;
    engine::FrameResult frame;
};

class Msaa : public engine::test::GlTest {
protected:
    // Ambient only by default: the square is one colour, the background another.
    Rendered render(engine::Scene& scene, int samples) {
        scene.updateWorldTransforms();
        engine::RendererConfig config;
        config.ambient = glm::vec3(1.0f);
        config.msaa = samples;
        engine::Renderer renderer(config, {});
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = squareCamera();
        Rendered out;
        out.frame = renderer.renderFrame(request);
        out.rgba = renderer.readColor();
        return out;
    }
};

std::uint8_t red(const std::vector<std::uint8_t>& rgba, int x, int y) { return rgba[(y * kImageSize + x) * 4]; }

TEST_F(Msaa, EdgesGetIntermediateValuesOnlyWithSamples) {
    engine::Scene scene = turnedSquare();
    const Rendered single = render(scene, 1);
    const Rendered multi = render(scene, 4);
    const std::uint8_t background = red(single.rgba, 0, 0);
    const std::uint8_t square = red(single.rgba, kImageSize / 2, kImageSize / 2);
    ASSERT_GT(square, background + 100) << "the square must stand out from the background";
    int singleBetween = 0, multiBetween = 0, squarePixels = 0;
    for (int y = 0; y < kImageSize; ++y)
        for (int x = 0; x < kImageSize; ++x) {
            const std::uint8_t a = red(single.rgba, x, y), b = red(multi.rgba, x, y);
            singleBetween += a != background && a != square;
            multiBetween += b > background && b < square;
            squarePixels += a == square;
        }
    std::printf("square: %d pixels; strictly between background %d and square %d: msaa 1 %d, msaa 4 %d\n",
                squarePixels, background, square, singleBetween, multiBetween);
    // Single-sampled, a pixel is the square or the background: nothing between.
    EXPECT_EQ(singleBetween, 0);
    // Four samples: every edge pixel with 1 to 3 of its 4 samples on the square is between.
    // The square's outline is 4 x 0.6 / 1.86 x 128 = 165 pixels long and every edge slants;
    // a pixel the edge barely crosses still has 0 or 4 samples on the square (measured: 108
    // between). Half the outline's length bounds it from below with room for another
    // implementation's sample positions, far above a staircase's 0.
    EXPECT_GT(multiBetween, 80);
    // The resolve averages in linear light, after tone mapping: an edge pixel with k of its 4
    // samples on the square (background black) is k/4 of the square's linear value, encoded
    // (measured: 99, 136 and 164 for a square of 187; an average of the sRGB-encoded values
    // would give 47, 94 and 140). 1/255: the 8-bit rounding of the decoded square and of the
    // re-encode.
    ASSERT_EQ(background, 0);
    const double squareLinear = srgbDecode(square / 255.0);
    int unexplained = 0;
    for (int i = 0; i < kImageSize * kImageSize; ++i) {
        const int b = multi.rgba[i * 4];
        if (b == background || b == square) continue;
        bool explained = false;
        for (int k = 1; k < 4; ++k)
            explained = explained || std::abs(b - 255.0 * srgbEncode(squareLinear * k / 4.0)) <= 1.0;
        unexplained += !explained;
    }
    EXPECT_EQ(unexplained, 0);
    // Only the shaded image is multisampled, resolved by a pass of its own.
    const auto hasPass = [](const engine::FrameResult& frame, const std::string& name) {
        return std::any_of(frame.passes.begin(), frame.passes.end(),
                           [&](const engine::PassReport& pass) { return pass.name == name && !pass.culled; });
    };
    EXPECT_TRUE(hasPass(multi.frame, "lit_resolve"));
    EXPECT_NE(multi.frame.graphviz.find("4 samples"), std::string::npos) << multi.frame.graphviz;
    // msaa 1 skips that work: no multisampled target, no resolve.
    EXPECT_FALSE(hasPass(single.frame, "lit_resolve"));
    EXPECT_EQ(single.frame.graphviz.find("samples"), std::string::npos) << single.frame.graphviz;
}

TEST_F(Msaa, AwayFromEdgesTheImagesAgree) {
    // Lit by a point light off to the side: the square's shade varies from pixel to pixel
    // (diffuse fall-off and a highlight), so agreement means the same shading, not one colour.
    engine::Scene scene = turnedSquare();
    addLight(scene, engine::Light::Type::Point, {0.4, 0.3, 1.0}, 2.0f);
    const Rendered single = render(scene, 1);
    const Rendered multi = render(scene, 4);
    int compared = 0, worst = 0;
    for (int y = 1; y + 1 < kImageSize; ++y)
        for (int x = 1; x + 1 < kImageSize; ++x) {
            // The square's inside: its 3x3 neighbourhood all square (no background pixel).
            bool inside = true;
            for (int dy = -1; dy <= 1 && inside; ++dy)
                for (int dx = -1; dx <= 1 && inside; ++dx)
                    inside = red(single.rgba, x + dx, y + dy) != red(single.rgba, 0, 0);
            if (!inside) continue;
            ++compared;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(int(single.rgba[(y * kImageSize + x) * 4 + c]) -
                                                 int(multi.rgba[(y * kImageSize + x) * 4 + c])));
        }
    std::printf("%d pixels inside the square; largest difference msaa 4 vs 1: %d / 255\n", compared, worst);
    EXPECT_GT(compared, 1200);  // the square covers 1708 pixels, 1504 of them away from its edges
    // A covered pixel runs its fragment shader once, at the pixel centre as without samples
    // (no per-sample shading, no centroid), and its samples all take that colour: the resolve
    // averages equal values. The only change is the resolve's sRGB decode and re-encode of an
    // 8-bit value, which round-trips exactly (measured: 0 on llvmpipe); 1/255 allows an
    // implementation that rounds the re-encode the other way.
    EXPECT_LE(worst, 1);
}

TEST_F(Msaa, MoreSamplesThanTheGlOffersIsAnErrorNamingTheKey) {
    const int most = engine::maxMsaaSamples();
    std::printf("this GL offers at most %d samples for the shaded image's targets\n", most);
    RecordProperty("max_samples", std::to_string(most));
    int tooMany = 0;  // the smallest count renderer.msaa accepts that this GL cannot give
    for (const int samples : engine::kMsaaSampleCounts)
        if (samples > most) {
            tooMany = samples;
            break;
        }
    if (tooMany == 0) GTEST_SKIP() << "this GL offers every count renderer.msaa accepts";
    engine::RendererConfig config;
    config.msaa = tooMany;
    try {
        engine::Renderer renderer(config, {});
        FAIL() << "msaa " << tooMany << " accepted";
    } catch (const engine::InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("renderer.msaa: " + std::to_string(tooMany) + " samples asked for"), std::string::npos)
            << message;
        EXPECT_NE(message.find("at most " + std::to_string(most)), std::string::npos) << message;
    }
}

} // namespace
