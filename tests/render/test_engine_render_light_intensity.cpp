// engine-render --light-set NAME.intensity=I and NAME.color=[r,g,b]: the light's own values
// replaced for the render, as if the file said so, the light's shadow untouched, and bad
// values refused before anything renders. Every image compared here is rendered in this run.
#include "EngineRenderRun.h"

#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using engine_render_test::CommandResult;
using engine_render_test::runEngineRender;

// The showcase's three lights by name, as its file gives them.
const char* const kLights[] = {"spot_light", "sun", "point_light"};

class EngineRenderLightIntensity : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("engine_render_light_intensity_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
        scene_ = engine_render_test::copyContentScene(dir_, "showcase");
    }
    void TearDown() override { fs::remove_all(dir_); }

    nlohmann::json& light(const std::string& name) { return engine_render_test::lightNamed(scene_, name); }
    double fileIntensity(const std::string& name) { return light(name)["intensity"].get<double>(); }

    // The (edited) scene rendered small into `stem`.png (and its stats), with `extra` flags.
    CommandResult render(const std::string& stem, const std::string& extra = "") {
        std::ofstream(dir_ / "scene.gltf") << scene_.dump();
        return runEngineRender("--config " + std::string(CONTENT_DIR) + "/engine.json --scene " +
                               (dir_ / "scene.gltf").string() + " --out " + (dir_ / (stem + ".png")).string() +
                               " --stats " + (dir_ / (stem + ".json")).string() +
                               " --width 160 --height 90 --warmup 0 " + extra);
    }
    std::vector<std::uint8_t> image(const std::string& stem) {
        int width = 0, height = 0;
        return engine::readPng(dir_ / (stem + ".png"), 4, width, height);
    }
    nlohmann::json stats(const std::string& stem) {
        std::ifstream in(dir_ / (stem + ".json"));
        return nlohmann::json::parse(in);
    }

    // --light-set options scaling every light's intensity by `factor`.
    std::string scaledLights(double factor) {
        std::string options;
        for (const char* name : kLights)
            options += " --light-set " + std::string(name) + ".intensity=" + std::to_string(fileIntensity(name) * factor);
        return options;
    }

    fs::path dir_;
    nlohmann::json scene_;
};

// sRGB-encoded 8-bit value to linear (IEC 61966-2-1).
double linear(std::uint8_t code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// The override is the file edited: the same light and value give the same bytes (same
// machine, same run), and the image differs from the file's own.
TEST_F(EngineRenderLightIntensity, OverrideRendersAsTheEditedFileDoes) {
    const std::string sunIntensity = std::to_string(fileIntensity("sun") * 0.5);
    ASSERT_EQ(render("file").exitCode, 0);
    const CommandResult overridden =
        render("overridden", "--light-set sun.intensity=" + sunIntensity + " --light-set spot_light.color=[0.5,1,0.25]");
    ASSERT_EQ(overridden.exitCode, 0) << overridden.output;
    light("sun")["intensity"] = std::stod(sunIntensity);
    light("spot_light")["color"] = {0.5, 1.0, 0.25};
    ASSERT_EQ(render("edited").exitCode, 0);
    EXPECT_EQ(image("overridden"), image("edited"));
    EXPECT_NE(image("overridden"), image("file"));
}

// The shaded radiance is ambient + the lights' terms, each proportional to its intensity
// (lit.frag), so with every light at k times its intensity a pixel's linear value is
// A + k * D. Renders at k = 0, 1/4 and 1/2 then differ by D/4 and D/2: twice the brightness
// added, measured on the pixels none of the three saturates. The sum over thousands of
// pixels averages the 8-bit rounding out (each pixel's error at most half a code, a few
// percent of a dim pixel's value, unbiased): 3 % bounds the ratio's error.
TEST_F(EngineRenderLightIntensity, IntensityScalesTheLightAddedToThePicture) {
    ASSERT_EQ(render("dark", scaledLights(0.0)).exitCode, 0);
    ASSERT_EQ(render("quarter", scaledLights(0.25)).exitCode, 0);
    ASSERT_EQ(render("half", scaledLights(0.5)).exitCode, 0);
    const std::vector<std::uint8_t> dark = image("dark"), quarter = image("quarter"), half = image("half");
    ASSERT_EQ(dark.size(), half.size());
    double addedQuarter = 0.0, addedHalf = 0.0;
    int measured = 0, saturated = 0;
    for (std::size_t pixel = 0; pixel + 3 < half.size(); pixel += 4) {
        bool clipped = false;
        for (int c = 0; c < 3; ++c) clipped = clipped || half[pixel + c] == 255;
        saturated += clipped;
        if (clipped) continue;
        ++measured;
        for (int c = 0; c < 3; ++c) {
            addedQuarter += linear(quarter[pixel + c]) - linear(dark[pixel + c]);
            addedHalf += linear(half[pixel + c]) - linear(dark[pixel + c]);
        }
    }
    // Most of the picture measured, and lit: the lights add light at all.
    EXPECT_GT(measured, static_cast<int>(half.size() / 4) * 3 / 4) << saturated << " saturated";
    ASSERT_GT(addedQuarter, 0.01 * measured);
    EXPECT_NEAR(addedHalf / addedQuarter, 2.0, 0.06);
}

// Intensity 0 is a light that emits nothing: --truth says it is not scored, and its shadow
// map is skipped for that reason. Another intensity leaves every shadow setting and the
// shadow itself (its mask) as they were.
TEST_F(EngineRenderLightIntensity, IntensityLeavesTheShadowAlone) {
    const std::string masks = " --shadow-mask sun=" + (dir_ / "sun_mask.png").string();
    ASSERT_EQ(render("file", masks).exitCode, 0);
    const std::vector<std::uint8_t> fileMask = engine_render_test::readMask(dir_ / "sun_mask.png");
    const CommandResult bright = render("bright", masks + " --light-set sun.intensity=3.5");
    ASSERT_EQ(bright.exitCode, 0) << bright.output;
    EXPECT_EQ(engine_render_test::readMask(dir_ / "sun_mask.png"), fileMask);
    const nlohmann::json before = stats("file")["plugins"]["shadowmap_plugin"]["lights"];
    const nlohmann::json after = stats("bright")["plugins"]["shadowmap_plugin"]["lights"];
    ASSERT_EQ(before.size(), 3u);
    ASSERT_EQ(after.size(), before.size());
    for (std::size_t i = 0; i < before.size(); ++i)
        for (const char* key : {"light", "variant", "resolution", "depth_format", "filter", "polygon_offset", "dimming", "map"})
            EXPECT_EQ(after[i][key], before[i][key]) << before[i]["light"] << " " << key;

    const CommandResult off = render("off", "--truth --light-set sun.intensity=0");
    ASSERT_EQ(off.exitCode, 0) << off.output;
    EXPECT_TRUE(std::regex_search(off.output, std::regex("\\n  sun +not scored: the light emits nothing")))
        << off.output;
    const nlohmann::json offStats = stats("off");
    const nlohmann::json* sun = engine_render_test::lightEntry(offStats["plugins"]["shadowmap_plugin"]["lights"], "sun");
    ASSERT_NE(sun, nullptr);
    EXPECT_EQ(sun->value("skip_reason", ""), "the light emits nothing");
}

// A bad value or an unknown light is one line naming the option, the light, the key and
// the value, and nothing is written.
TEST_F(EngineRenderLightIntensity, BadValuesAndUnknownLightsAreRefused) {
    const auto expectRefused = [&](const std::string& option, const std::vector<std::string>& parts) {
        const CommandResult result = render("refused", option);
        EXPECT_EQ(result.exitCode, 1) << option << "\n" << result.output;
        for (const std::string& part : parts) EXPECT_NE(result.output.find(part), std::string::npos) << result.output;
        EXPECT_FALSE(fs::exists(dir_ / "refused.png")) << option;
    };
    expectRefused("--light-set sun.intensity=-2",
                  {"--light-set sun.intensity=-2: light \"sun\".intensity must be a finite number >= 0", "got -2"});
    expectRefused("--light-set sun.intensity=bright", {"light \"sun\".intensity", "got \"bright\""});
    expectRefused("--light-set sun.color=[1,1]", {"light \"sun\".color must be [r, g, b]", "got [1,1]"});
    expectRefused("--light-set moon.intensity=2", {"light \"moon\"", "no such light"});
    expectRefused("--light-set sun.intensity=2 --light-set 2.intensity=3", {"already set by --light-set sun.intensity=2"});
}

} // namespace
