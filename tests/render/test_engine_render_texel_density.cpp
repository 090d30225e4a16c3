// engine-render --texel-density NAME=HEAT.png (truth/TexelDensityImage.h): the heat map of a
// map texel's size on screen, m, per pixel. End to end on the showcase: the sun's default map
// (2048, one layer) at 1280x720 is close to one texel per pixel over most of what it lights,
// so most of its heat map is green; bad names and paths are refused with one line before
// anything is rendered. Every image is rendered in this run.
#include "EngineRenderRun.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

using engine_render_test::runEngineRender;

// The documented grey of "no value" (docs/metrics.md, "Texel on screen").
constexpr std::uint8_t kNoValueGrey = 128;

bool noValue(const std::uint8_t* rgb) { return rgb[0] == kNoValueGrey && rgb[1] == kNoValueGrey && rgb[2] == kNoValueGrey; }

// Green-ish: a colour of the scale between the blue-green and green-yellow midpoints, green at
// least 128 and red and blue at most 128, i.e. m within [2^-0.5, 2] (docs: 0.5 blue, 1 green,
// 4 yellow, log scale).
bool greenish(const std::uint8_t* rgb) { return rgb[1] >= 128 && rgb[0] <= 128 && rgb[2] <= 128; }

// Coarser than 2 pixels per texel: more red than the green-yellow midpoint, m > 2.
bool coarse(const std::uint8_t* rgb) { return rgb[0] > 128; }

// Measured on the showcase, sun, 1280x720 (llvmpipe): of the 613,188 pixels with a value, at
// the default map of 2048 70.0 % are green-ish and 2.9 % coarse (--truth: m mean 1.11, p95
// 1.41; the rest is the far ground, m < 0.7, blue, and the cube's side and the sphere's and
// torus's rims, grazing the sun, yellow to red). The same run at 1024: 64.6 % green-ish, 34.8 %
// coarse; at 4096: 2.9 % green-ish. The bounds leave a few percent for another renderer's
// coverage and catch a map twice as coarse or as fine.
constexpr double kMinGreenish = 0.6, kMaxCoarse = 0.1;

class EngineRenderTexelDensity : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("engine_render_texel_density_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string common(int width, int height) const {
        return std::string("--config ") + CONTENT_DIR + "/engine.json --scene " + CONTENT_DIR +
               "/scenes/showcase.gltf --out '" + (dir_ / "out.png").string() + "' --width " + std::to_string(width) +
               " --height " + std::to_string(height);
    }

    fs::path dir_;
};

} // namespace

TEST_F(EngineRenderTexelDensity, TheShowcaseSunsMapIsAboutOneTexelPerPixel) {
    constexpr int kWidth = 1280, kHeight = 720;
    const fs::path heat = dir_ / "sun_density.png";
    const auto run = runEngineRender(common(kWidth, kHeight) + " --texel-density sun='" + heat.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("texel density: m (px per texel)"), std::string::npos) << run.output;

    int width = 0, height = 0;
    const std::vector<std::uint8_t> rgb = engine::readPng(heat, 3, width, height);
    ASSERT_EQ(width, kWidth);
    ASSERT_EQ(height, kHeight);
    std::size_t valued = 0, green = 0, coarser = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
        if (noValue(&rgb[i])) continue;
        ++valued;
        green += greenish(&rgb[i]);
        coarser += coarse(&rgb[i]);
    }
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    // The sky has no surface: grey; the ground and the objects have values.
    ASSERT_GT(valued, pixels / 2);
    ASSERT_LT(valued, pixels);
    const double share = static_cast<double>(green) / static_cast<double>(valued);
    const double coarseShare = static_cast<double>(coarser) / static_cast<double>(valued);
    std::printf("of %zu pixels with a value: green-ish %.1f %%, coarse %.1f %%\n", valued, 100.0 * share,
                100.0 * coarseShare);
    EXPECT_GE(share, kMinGreenish);
    EXPECT_LE(coarseShare, kMaxCoarse);
}

// Each bad --texel-density is one line and exit 1, and nothing is rendered or written: the
// light is resolved and the path checked before the first frame.
TEST_F(EngineRenderTexelDensity, RefusesBadNamesAndPathsWithOneLine) {
    const std::string good = (dir_ / "heat.png").string();
    const std::pair<std::string, std::string> cases[] = {
        {"no_such_light='" + good + "'", "light \"no_such_light\": no such light"},
        {"sun='" + (dir_ / "missing" / "heat.png").string() + "'", "does not exist"},
        {"sun='" + (dir_ / "heat.jpg").string() + "'", "writes PNG only"},
        {"sun", "must be NAME=VALUE"},
        {"sun='" + (dir_ / "out.png").string() + "'", "named for two outputs"},
    };
    for (const auto& [argument, reason] : cases) {
        const auto run = runEngineRender(common(64, 36) + " --texel-density " + argument);
        EXPECT_EQ(run.exitCode, 1) << argument << ": " << run.output;
        EXPECT_NE(run.output.find(reason), std::string::npos) << argument << ": " << run.output;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << argument << ": " << run.output;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << argument << ": rendered before refusing";
        EXPECT_FALSE(fs::exists(good)) << argument;
    }
}

// A light without a map this frame (variant none) has no texels to measure: said in one line.
TEST_F(EngineRenderTexelDensity, RefusesALightWithoutAMap) {
    const auto run = runEngineRender(common(64, 36) + " --light sun=none --texel-density sun='" +
                                     (dir_ / "heat.png").string() + "'");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("--texel-density sun: the light has no shadow map"), std::string::npos) << run.output;
}
