// engine-render --exposure auto (tools/engine-render/AutoExposure.h): the exposure that maps
// the first frame's log-average luminance to middle grey 0.18, metered from probe renders of
// that frame. Lights in physical units (Blender 4 writes a 1000 W spot as 54,351 cd) no
// longer blow the picture to white; what is measured is checked on the image written.
// Every image is rendered in this run: nothing is compared with a stored picture.
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

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

using engine_render_test::CommandResult;
using engine_render_test::runEngineRender;

// Blender 4's glTF exporter writes a 1000 W spot light as 54,351 cd (W / (4 pi) * 683 lm/W):
// the showcase's lights are scaled so that its spot has that intensity, the others by the
// same factor (a scene lit in physical units throughout).
constexpr double kBlenderSpotCandela = 54351.0;
// engine-render's warning threshold (main.cpp's kMostlySaturated): above it, "most of the
// image" is saturated and the tool says so.
constexpr double kMostlySaturated = 0.5;
constexpr const char* kSaturationWarning = "of the image is saturated";

// sRGB-encoded 8-bit value to linear (IEC 61966-2-1).
double linear(std::uint8_t code) {
    const double v = code / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// What the tests read off an RGBA8 image.
struct ImageFigures {
    double saturated = 0.0;   // share of all pixels with a channel at 255
    double logAverage = 0.0;  // exp(mean ln luminance) over the pixels that are not black
    std::size_t measured = 0; // those pixels
};
ImageFigures figures(const std::vector<std::uint8_t>& rgba) {
    ImageFigures out;
    std::size_t saturated = 0;
    double sumLog = 0.0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        saturated += rgba[i] == 255 || rgba[i + 1] == 255 || rgba[i + 2] == 255;
        const double luminance = 0.2126 * linear(rgba[i]) + 0.7152 * linear(rgba[i + 1]) + 0.0722 * linear(rgba[i + 2]);
        if (luminance == 0.0) continue;
        sumLog += std::log(luminance);
        ++out.measured;
    }
    out.saturated = static_cast<double>(saturated) / static_cast<double>(rgba.size() / 4);
    out.logAverage = out.measured ? std::exp(sumLog / static_cast<double>(out.measured)) : 0.0;
    return out;
}

// The EV100 that "auto exposure: EV100 x.xx" printed; NaN when it printed none.
double printedEv100(const std::string& output) {
    std::smatch match;
    if (!std::regex_search(output, match, std::regex("auto exposure: EV100 (-?[0-9]+\\.[0-9]{2}) ")))
        return std::nan("");
    return std::stod(match[1].str());
}

class EngineRenderAutoExposure : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("engine_render_auto_exposure_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
        scene_ = engine_render_test::copyContentScene(dir_, "showcase");
        // The repository's config with a black background: the background is no radiance of
        // the scene, and black pixels are what the meter (and figures()) leave out.
        std::ifstream configIn(fs::path(CONTENT_DIR) / "engine.json");
        nlohmann::json config = nlohmann::json::parse(configIn);
        config["renderer"]["clear_color"] = {0.0, 0.0, 0.0};
        std::ofstream(dir_ / "engine.json") << config.dump();
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Every light's intensity times `factor`.
    void scaleLights(double factor) {
        for (auto& light : scene_["extensions"]["KHR_lights_punctual"]["lights"])
            light["intensity"] = light.value("intensity", 1.0) * factor;
    }
    double spotIntensity() { return engine_render_test::lightNamed(scene_, "spot_light")["intensity"].get<double>(); }

    // The (edited) scene at 320x180 (under the probes' 512-pixel side: they render these pixels).
    CommandResult render(const std::string& extra = "") {
        std::ofstream(dir_ / "scene.gltf") << scene_.dump();
        return runEngineRender("--config " + (dir_ / "engine.json").string() + " --scene " +
                               (dir_ / "scene.gltf").string() + " --out " + (dir_ / "out.png").string() +
                               " --width 320 --height 180 --warmup 0 " + extra);
    }
    std::vector<std::uint8_t> image() {
        int width = 0, height = 0;
        return engine::readPng(dir_ / "out.png", 4, width, height);
    }

    fs::path dir_;
    nlohmann::json scene_;
};

// The showcase lit as Blender 4 would write it: at the default exposure (1) most of the
// picture is white and the tool warns; with --exposure auto the picture is exposed for its
// log-average, the warning is gone, and what saturates is the few pixels more than
// 1 / 0.18 = 5.6 times (2.5 stops) brighter than that average: the highlights. Measured
// (llvmpipe, 320x180): 67 % saturated at exposure 1, 0.2 % with auto (EV100 8.92); the
// bound, 2 %, is ten times that, far below "most of the image".
TEST_F(EngineRenderAutoExposure, PhysicalUnitsSaturateWithoutItAndNotWithIt) {
    scaleLights(kBlenderSpotCandela / spotIntensity());
    ASSERT_NEAR(spotIntensity(), kBlenderSpotCandela, 1e-6);
    const CommandResult plain = render();
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    const ImageFigures before = figures(image());
    EXPECT_GT(before.saturated, kMostlySaturated);
    EXPECT_NE(plain.output.find(kSaturationWarning), std::string::npos) << plain.output;
    EXPECT_NE(plain.output.find("--exposure auto"), std::string::npos) << plain.output;

    const CommandResult exposed = render("--exposure auto");
    ASSERT_EQ(exposed.exitCode, 0) << exposed.output;
    const ImageFigures after = figures(image());
    EXPECT_LT(after.saturated, 0.02) << "saturated share with auto: " << after.saturated << "\n" << exposed.output;
    EXPECT_EQ(exposed.output.find(kSaturationWarning), std::string::npos) << exposed.output;
    // A physical-units scene meters well above display units' EV100 of about 0.
    EXPECT_GT(printedEv100(exposed.output), 5.0) << exposed.output;
}

// On the image written, the log-average luminance of the scene's pixels is middle grey. It is
// the metered value up to what the 8-bit image does to it: pixels that saturate are clamped
// (pulling the average down), pixels that round to black are left out (pushing it up), each
// a fraction of a percent of the pixels here, and the rounding of each pixel (unbiased)
// averages out. Measured: 0.181 (showcase), 0.185 (in physical units); the band is 5 %.
TEST_F(EngineRenderAutoExposure, MapsTheLogAverageToMiddleGrey) {
    const CommandResult result = render("--exposure auto");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_FALSE(std::isnan(printedEv100(result.output))) << result.output;
    const ImageFigures shown = figures(image());
    EXPECT_GT(shown.measured, 320u * 180u / 4) << "most of the frame is the scene";
    EXPECT_NEAR(shown.logAverage, 0.18, 0.05 * 0.18) << result.output;
}

// The meter is linear: lights 10 times brighter meter log2(10) = 3.32 stops higher. Both
// renders are in physical units, where the ambient term (display units, not scaled) is
// 10^-4 of the lights' and moves neither; the 8-bit rounding of each probe pixel (at most
// about 5 %, unbiased) averages out over the frame: within 0.05 EV (measured 3.30).
TEST_F(EngineRenderAutoExposure, TenTimesTheLightIsThreeAndAThirdStops) {
    scaleLights(1000.0);
    const CommandResult dimmer = render("--exposure auto");
    ASSERT_EQ(dimmer.exitCode, 0) << dimmer.output;
    scaleLights(10.0);
    const CommandResult brighter = render("--exposure auto");
    ASSERT_EQ(brighter.exitCode, 0) << brighter.output;
    EXPECT_NEAR(printedEv100(brighter.output) - printedEv100(dimmer.output), std::log2(10.0), 0.05)
        << dimmer.output << brighter.output;
}

// Chosen once, from the first frame: an orbit of three frames meters once and says so once.
TEST_F(EngineRenderAutoExposure, ChosenOnceForAllFrames) {
    const CommandResult result = render("--exposure auto --frames 3 --orbit-camera");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::regex said("auto exposure: ");
    EXPECT_EQ(std::distance(std::sregex_iterator(result.output.begin(), result.output.end(), said),
                            std::sregex_iterator()),
              1)
        << result.output;
}

TEST_F(EngineRenderAutoExposure, BadValuesAreRefused) {
    for (const char* bad : {"--exposure automatic", "--exposure auto --exposure 12", "--exposure 31"}) {
        const CommandResult result = render(bad);
        EXPECT_EQ(result.exitCode, 1) << bad << "\n" << result.output;
        EXPECT_NE(result.output.find("--exposure"), std::string::npos) << result.output;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << bad;
    }
}

} // namespace
