// engine-render with the shadow plugin, end to end: per-light choices from glTF, config and
// command line; bad settings end in exit code 1 and one line naming the light and the key.
#include "../../render/EngineRenderRun.h"
#include "engine/util/OutputFile.h"
#include "engine/util/Version.h"

#include "../../support/AssimpTestModels.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <vector>

namespace {

// A PNG's pixels (RGBA), to compare two renders made in this run.
std::vector<std::uint8_t> readImage(const std::filesystem::path& file) {
    int width = 0, height = 0;
    return engine::readPng(file, 4, width, height);
}

namespace fs = std::filesystem;

using engine_render_test::CommandResult;
using engine_render_test::runEngineRender;

class EngineRenderShadows : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("engine_render_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(dir_);
        useScene("showcase");
    }

    // Renders content/scenes/NAME.gltf (with its .bin) from now on; the showcase by default.
    void useScene(const std::string& name) { scene_ = engine_render_test::copyContentScene(dir_, name); }
    void TearDown() override { fs::remove_all(dir_); }

    nlohmann::json& light(const std::string& name) { return engine_render_test::lightNamed(scene_, name); }

    // The node that places the light (camera) called `name`.
    nlohmann::json& nodeNamed(const std::string& name) {
        for (auto& node : scene_["nodes"])
            if (node.value("name", "") == name) return node;
        throw std::runtime_error("no node " + name);
    }

    // The entry of --stats' plugin report for one light.
    nlohmann::json pluginLightStats(const std::string& name) {
        const nlohmann::json all = stats();
        for (const auto& entry : all["plugins"]["shadowmap_plugin"]["lights"])
            if (entry["light"] == name) return entry;
        throw std::runtime_error("no stats for light " + name + " in " + all.dump());
    }

    // Writes the (edited) scene and renders it small.
    CommandResult render(const std::string& extra = "", const std::string& config = "engine.json") {
        std::ofstream(dir_ / "scene.gltf") << scene_.dump();
        return runEngineRender("--config " + std::string(CONTENT_DIR) + "/" + config + " --scene " +
                   (dir_ / "scene.gltf").string() + " --out " + (dir_ / "out.png").string() +
                   " --width 96 --height 64 --warmup 0 --stats " + (dir_ / "stats.json").string() + " " +
                   extra);
    }

    // The showcase's (or masked scenes') three lights at 480x270 with --truth, sized by
    // `sizes` (--light-set options) and each given `key`=`value` (none when key is empty):
    // --stats' per-light entries, three of them, in the lights' order.
    nlohmann::json everyLightWith(const std::string& sizes, const std::string& key = "", const std::string& value = "") {
        std::string options = "--width 480 --height 270 --truth " + sizes;
        if (!key.empty())
            for (const char* name : {"sun", "spot_light", "point_light"})
                options += std::string(" --light-set ") + name + "." + key + "=" + value;
        const CommandResult result = render(options);
        EXPECT_EQ(result.exitCode, 0) << result.output;
        nlohmann::json lights = result.exitCode == 0 ? stats()["lights"] : nlohmann::json::array();
        EXPECT_EQ(lights.size(), 3u) << lights.dump();
        return lights.size() == 3u ? lights : nlohmann::json();
    }

    nlohmann::json stats() {
        std::ifstream in(dir_ / "stats.json");
        return nlohmann::json::parse(in);
    }

    // Whether light `slot`'s map was drawn in the run (not served from the cache, not
    // skipped), from the shadow views engine-render reports, not from graph pass names.
    bool drewShadowMap(int slot) {
        const nlohmann::json all = stats();  // kept: a range-for over stats()[...] would dangle
        for (const auto& map : all["shadow_maps"])
            if (map["slot"] == slot) return map["map"] != "none" && !map["map_cached"].get<bool>();
        throw std::runtime_error("no shadow_maps entry for slot " + std::to_string(slot) + " in " + all.dump());
    }

    void expectError(const CommandResult& result, std::initializer_list<const char*> fragments) {
        EXPECT_EQ(result.exitCode, 1) << result.output;
        for (const char* fragment : fragments)
            EXPECT_NE(result.output.find(fragment), std::string::npos)
                << "missing \"" << fragment << "\" in: " << result.output;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << "a failed run must not leave an image";
    }

    fs::path dir_;
    nlohmann::json scene_;
};

} // namespace

TEST_F(EngineRenderShadows, EveryLightTypeGetsItsDepthPass) {
    const CommandResult result = render();
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(drewShadowMap(0));
    EXPECT_TRUE(drewShadowMap(1));
    EXPECT_TRUE(drewShadowMap(2));
    int width = 0, height = 0;
    EXPECT_EQ(engine::readPng(dir_ / "out.png", 4, width, height).size(), 96u * 64u * 4u);
}

TEST_F(EngineRenderShadows, VariantNoneCostsNoPassFromGltfAndFromTheCommandLine) {
    light("sun")["extras"]["shadow"]["variant"] = "none";
    const CommandResult result = render("--light point_light=none");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(drewShadowMap(0));
    EXPECT_FALSE(drewShadowMap(1));
    EXPECT_FALSE(drewShadowMap(2));
    const nlohmann::json all = stats();
    for (const auto& entry : all["plugins"]["shadowmap_plugin"]["lights"])
        if (entry["light"] != "spot_light") {
            EXPECT_EQ(entry["skip_reason"], "variant none");
        }
}

TEST_F(EngineRenderShadows, ConfigDefaultsApplyWhereTheLightIsSilent) {
    light("sun")["extras"]["shadow"].erase("resolution");
    const CommandResult result = render();
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    for (const auto& entry : all["plugins"]["shadowmap_plugin"]["lights"]) {
        if (entry["light"] == "sun") {
            EXPECT_EQ(entry["resolution"], 2048);  // from the config
        } else if (entry["light"] == "point_light") {
            EXPECT_EQ(entry["resolution"], 1024);  // from the glTF
        }
    }
}

TEST_F(EngineRenderShadows, ShadowMaskWorksForEveryLightType) {
    const CommandResult result = render("--shadow-mask spot_light=" + (dir_ / "spot.png").string() +
                              " --shadow-mask sun=" + (dir_ / "sun.png").string() +
                              " --shadow-mask point_light=" + (dir_ / "point.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* file : {"spot.png", "sun.png", "point.png"}) {
        int width = 0, height = 0;
        const auto mask = engine::readPng(dir_ / file, 1, width, height);
        ASSERT_EQ(mask.size(), 96u * 64u) << file;
        int shadowed = 0, lit = 0;
        for (std::uint8_t value : mask) (value == 0 ? shadowed : lit) += (value == 0 || value == 255);
        EXPECT_GT(shadowed, 50) << file;  // every light casts some shadow in the showcase
        EXPECT_GT(lit, 500) << file;
    }
}

TEST_F(EngineRenderShadows, UnknownVariantNamesTheLight) {
    light("sun")["extras"]["shadow"]["variant"] = "wooo";
    expectError(render(), {"light \"sun\"", "extras.shadow.variant", "unknown variant \"wooo\""});
}

TEST_F(EngineRenderShadows, UnknownKeyNamesTheLightAndTheKey) {
    light("spot_light")["extras"]["shadow"]["bias"] = 0.1;
    expectError(render(), {"light \"spot_light\"", "extras.shadow.bias", "unknown key"});
}

TEST_F(EngineRenderShadows, ZeroResolutionIsRefused) {
    light("sun")["extras"]["shadow"]["resolution"] = 0;
    expectError(render(), {"light \"sun\"", "resolution", ">= 1"});
}

TEST_F(EngineRenderShadows, ResolutionAboveTheGlLimitIsRefused) {
    light("sun")["extras"]["shadow"]["resolution"] = 262144;
    expectError(render(), {"light \"sun\"", "resolution", "GL_MAX_TEXTURE_SIZE"});
}

TEST_F(EngineRenderShadows, DimmingOutOfRangeIsRefused) {
    light("point_light")["extras"]["shadow"]["dimming"] = 1.5;
    expectError(render(), {"light \"point_light\"", "dimming", "[0, 1]"});
}

TEST_F(EngineRenderShadows, ConeAngleOutOfRangeIsRefused) {
    light("spot_light")["spot"]["outerConeAngle"] = 2.0;
    expectError(render(), {"scene.gltf", "spot_light", "outerConeAngle"});
}

TEST_F(EngineRenderShadows, CommandLineLightMustExistAndVariantMustBeKnown) {
    // The error lists the lights there are, numbered as --list numbers them.
    expectError(render("--light nosuchlight=standard"),
                {"light \"nosuchlight\"", "no such light", "the scene's lights: 1 spot_light, 2 sun, 3 point_light"});
    expectError(render("--shadow-mask nosuchlight=" + (dir_ / "m.png").string()),
                {"light \"nosuchlight\"", "the scene's lights: 1 spot_light"});
    expectError(render("--light sun=fuzzy"), {"sun=fuzzy", "unknown variant \"fuzzy\""});
    expectError(render("--light 4=none"), {"light \"4\"", "no such light"});  // three lights
}

TEST_F(EngineRenderShadows, UnknownCameraListsTheCameras) {
    expectError(render("--camera nosuchcamera"),
                {"scene.gltf", "camera \"nosuchcamera\"", "no such camera", "the scene's cameras: 1 main_camera"});
}

// --list: what the options can name, and nothing rendered.
TEST_F(EngineRenderShadows, ListPrintsCamerasAndLightsWithNumbersAndTypes) {
    std::ofstream(dir_ / "scene.gltf") << scene_.dump();
    const CommandResult result = runEngineRender("--scene " + (dir_ / "scene.gltf").string() + " --list");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* line : {"1 main_camera perspective", "1 spot_light spot", "2 sun directional", "3 point_light point"}) {
        // One line per object: its number, name and type, separated by spaces.
        std::string pattern = "(^|\n) *";
        for (const char c : std::string(line)) pattern += c == ' ' ? std::string(" +") : std::string(1, c);
        EXPECT_TRUE(std::regex_search(result.output, std::regex(pattern + "\n")))
            << "missing \"" << line << "\" in:\n" << result.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// A scene without cameras or lights says so in each section instead of leaving it empty.
TEST_F(EngineRenderShadows, ListSaysNoneForASectionWithoutEntries) {
    scene_.erase("cameras");
    scene_["extensions"].erase("KHR_lights_punctual");
    scene_.erase("extensionsUsed");
    for (auto& node : scene_["nodes"]) {
        node.erase("camera");
        if (node.contains("extensions")) node["extensions"].erase("KHR_lights_punctual");
    }
    std::ofstream(dir_ / "scene.gltf") << scene_.dump();
    const CommandResult result = runEngineRender("--scene " + (dir_ / "scene.gltf").string() + " --list");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(std::regex_search(result.output, std::regex("cameras[^\n]*\n +\\(none\\)"))) << result.output;
    EXPECT_TRUE(std::regex_search(result.output, std::regex("lights[^\n]*\n +\\(none: --key-light adds one\\)")))
        << result.output;
}

// --camera framing: the framing camera even in a scene that has its own (as engine-view's 0
// key), the same picture as the scene without its camera gives by default.
TEST_F(EngineRenderShadows, CameraFramingIsTheFramingCameraEvenWhenTheSceneHasOne) {
    const auto image = [&](const std::string& name) {
        return readImage(dir_ / name);
    };
    ASSERT_EQ(render("--camera framing").exitCode, 0);
    fs::rename(dir_ / "out.png", dir_ / "framing.png");
    ASSERT_EQ(render().exitCode, 0);
    fs::rename(dir_ / "out.png", dir_ / "own.png");
    scene_.erase("cameras");
    for (auto& node : scene_["nodes"]) node.erase("camera");
    ASSERT_EQ(render().exitCode, 0);
    EXPECT_EQ(image("framing.png"), image("out.png"));
    EXPECT_NE(image("framing.png"), image("own.png"));
}

// Without --config, a tool of the build tree started outside the checkout (here: in a
// temporary folder without content/) uses the source tree's engine.json, as an installed
// tool uses the install's.
TEST_F(EngineRenderShadows, RunsWithoutConfigFromAFolderOutsideTheCheckout) {
    std::ofstream(dir_ / "scene.gltf") << scene_.dump();
    const CommandResult result = runEngineRender("--scene scene.gltf --out out.png --width 32 --height 32 --warmup 0",
                                                 dir_);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

// Lights in physical units (here every light 10^4 times brighter, as candela would be) blow
// the picture to white at display exposure: a warning says so and names --exposure, which
// brings it back (EV100 13: no warning). The showcase as it is gets none.
TEST_F(EngineRenderShadows, AMostlySaturatedImageIsWarnedAboutAndExposureFixesIt) {
    const std::string warning = "of the image is saturated: the lights may be in physical units";
    const CommandResult plain = render();
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_EQ(plain.output.find(warning), std::string::npos) << plain.output;
    for (auto& light : scene_["extensions"]["KHR_lights_punctual"]["lights"])
        light["intensity"] = light.value("intensity", 1.0) * 1e4;
    const CommandResult bright = render();
    ASSERT_EQ(bright.exitCode, 0) << bright.output;
    EXPECT_NE(bright.output.find(warning), std::string::npos) << bright.output;
    EXPECT_NE(bright.output.find("--exposure EV100"), std::string::npos) << bright.output;
    const CommandResult exposed = render("--exposure 13");
    ASSERT_EQ(exposed.exitCode, 0) << exposed.output;
    EXPECT_EQ(exposed.output.find(warning), std::string::npos) << exposed.output;
    fs::remove(dir_ / "out.png");
    expectError(render("--exposure 99"), {"--exposure"});
}

// --version alone prints the engine's version; a typo as the last argument is an unknown
// option, as it is anywhere else on the line.
TEST_F(EngineRenderShadows, VersionAndATrailingTypoAreAnsweredAsAUserExpects) {
    const CommandResult version = runEngineRender("--version");
    EXPECT_EQ(version.exitCode, 0) << version.output;
    EXPECT_EQ(version.output, "engine-render " + std::string(engine::version()) + "\n");
    EXPECT_TRUE(std::regex_match(std::string(engine::version()), std::regex("[0-9]+\\.[0-9]+\\.[0-9]+")));
    const CommandResult typo = render("--trth");
    EXPECT_EQ(typo.exitCode, 1) << typo.output;
    EXPECT_NE(typo.output.find("unknown option --trth"), std::string::npos) << typo.output;
}

// glTF cameras and lights are often unnamed, their nodes too: the command line names them
// by their number in --list, and the plugin reports them under "light N".
TEST_F(EngineRenderShadows, UnnamedCameraAndLightAreChosenByNumber) {
    scene_["cameras"][0].erase("name");
    nodeNamed("main_camera").erase("name");
    light("sun").erase("name");
    nodeNamed("sun").erase("name");
    const CommandResult result = render("--camera 1 --light 2=none");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(pluginLightStats("light 2")["skip_reason"], "variant none");
    EXPECT_TRUE(drewShadowMap(0));
    EXPECT_TRUE(drewShadowMap(2));
}

// The rule's other half: a name wins over a number, so a light called "1" is that light.
TEST_F(EngineRenderShadows, ANameWinsOverANumber) {
    light("point_light")["name"] = "1";
    const CommandResult result = render("--light 1=none");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(pluginLightStats("1")["skip_reason"], "variant none");
    EXPECT_TRUE(drewShadowMap(0));  // light number 1 keeps its shadow
}

// engine-render writes PNG and nothing else: a file named .jpg would hold PNG bytes.
TEST_F(EngineRenderShadows, AnImageNamedOtherThanPngIsRefused) {
    std::ofstream(dir_ / "scene.gltf") << scene_.dump();
    const std::string common = "--config " + std::string(CONTENT_DIR) + "/engine.json --scene " +
                               (dir_ / "scene.gltf").string() + " --width 32 --height 32 ";
    for (const std::string& bad : {"--out " + (dir_ / "out.jpg").string(),
                                  "--out " + (dir_ / "out.png").string() + " --shadow-mask sun=" + (dir_ / "sun.bmp").string()}) {
        const CommandResult result = runEngineRender(common + bad);
        EXPECT_EQ(result.exitCode, 1) << bad << ": " << result.output;
        EXPECT_NE(result.output.find("writes PNG only"), std::string::npos) << result.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out.jpg"));
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    EXPECT_EQ(runEngineRender(common + "--out " + (dir_ / "upper.PNG").string()).exitCode, 0);
}

// Outputs are checked before the scene loads (OutputFile.h): a folder that does not exist, a
// file the user made read-only and one file named for two outputs each end the run at once,
// naming the file, and leave nothing written.
TEST_F(EngineRenderShadows, AnOutputThatCannotBeWrittenIsRefusedBeforeRendering) {
    expectError(render("--shadow-mask sun=" + (dir_ / "missing" / "sun.png").string()),
                {"sun.png: its folder", "missing does not exist"});
    expectError(render("--graph-dot " + (dir_ / "no" / "graph.dot").string()), {"graph.dot: its folder"});
    expectError(render("--shadow-map sun=" + (dir_ / "out.png").string()),
                {"out.png: named for two outputs"});

    const fs::path stats = dir_ / "stats.json";
    std::ofstream(stats) << "kept";
    fs::permissions(stats, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    expectError(render(), {"stats.json", "read-only: not replaced"});
    std::ifstream in(stats);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), "kept");
}

TEST_F(EngineRenderShadows, StatsReportEachLightsDimming) {
    light("sun")["extras"]["shadow"]["dimming"] = 0.25;
    const CommandResult result = render();
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(pluginLightStats("sun")["dimming"], 0.25);
    EXPECT_EQ(pluginLightStats("spot_light")["dimming"], 0.4);  // the default, written as set
}

// One way to write numbers in messages: 5, not 5.000000.
TEST_F(EngineRenderShadows, NumbersInMessagesAreWrittenAsPeopleWriteThem) {
    light("spot_light")["extras"]["shadow"]["near_plane"] = 5;
    light("spot_light")["extras"]["shadow"]["far_plane"] = 2.5;
    expectError(render(), {"light \"spot_light\"", "far_plane", "must be beyond near_plane (5), got 2.5"});
}

TEST_F(EngineRenderShadows, MissingPluginLibraryIsNamed) {
    std::ofstream(dir_ / "bad.json") << R"({"plugins":[{"library":"no_such_shadow_plugin"}]})";
    const CommandResult result = runEngineRender("--config " + (dir_ / "bad.json").string() + " --scene " +
                           (fs::path(CONTENT_DIR) / "scenes/showcase.gltf").string() + " --out " +
                           (dir_ / "out.png").string());
    expectError(result, {"bad.json", "no_such_shadow_plugin.so", "not found"});
}

TEST_F(EngineRenderShadows, ShadowMaskWithoutAShadowPluginIsAClearError) {
    expectError(render("--shadow-mask sun=" + (dir_ / "sun.png").string(), "engine-unshadowed.json"),
                {"--shadow-mask", "no loaded plugin provides a shadow term"});
}

// At 96x64 a light's evaluation set is 2900-4200 pixels, so one pixel is ~0.03 %: measured
// at most 0.114 % (the spot light, 2940 pixels); bound 0.25 %, four pixels of margin.
constexpr double kSmallImageErrorBound = 0.25;

TEST_F(EngineRenderShadows, TruthReportsTimeAndErrorPerShadowedLight) {
    light("sun")["extras"]["shadow"]["variant"] = "woo";
    const CommandResult result = render("--truth");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["lights"].size(), 3u) << all.dump();
    for (const auto& entry : all["lights"]) {
        EXPECT_GT(entry["evaluated_pixels"].get<int>(), 100) << entry;
        // The one frame rendered every map (--warmup 0, --frames 1), so each took time.
        EXPECT_FALSE(entry["map_cached"].get<bool>()) << entry;
        EXPECT_GT(entry["map_ms"].get<double>(), 0.0) << entry;
        EXPECT_LT(entry["error"].get<double>(), kSmallImageErrorBound) << entry;
        // Every light type (spot, directional, cube) has a texel size on screen.
        EXPECT_GT(entry["texel_m_mean"].get<double>(), 0.0) << entry;
        EXPECT_GT(entry["texel_m_p95"].get<double>(), 0.0) << entry;
        std::printf("%s: error %.3f %% of %d pixels, map %.2f ms\n", entry["light"].get<std::string>().c_str(),
                    entry["error"].get<double>(), entry["evaluated_pixels"].get<int>(), entry["map_ms"].get<double>());
        EXPECT_NE(result.output.find(entry["light"].get<std::string>()), std::string::npos);
    }
    EXPECT_EQ(all["lights"][1]["variant"], "woo");
    EXPECT_NE(result.output.find("texel m"), std::string::npos) << result.output;
}

// Lights are light instances (node + light), names only for people: one light placed by two
// nodes, and lights and nodes without names, render with every instance shadowed and scored
// (refused before: "resource 'shadow_map_spot_light' already imported"), within the bound
// that distinct lights hold below (error <= 0.25 % at 320x180 with 2048 maps).
TEST_F(EngineRenderShadows, OneLightPlacedByTwoNodesIsTwoShadowedInstances) {
    light("spot_light")["extras"]["shadow"]["resolution"] = 2048;
    nodeNamed("point_light")["extensions"]["KHR_lights_punctual"]["light"] = 0;  // the spot, placed again
    const CommandResult result = render("--width 320 --height 180 --truth");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["lights"].size(), 3u) << all.dump();
    std::vector<int> spotSlots;
    for (const auto& entry : all["lights"]) {
        EXPECT_GT(entry["evaluated_pixels"].get<int>(), 1000) << entry;
        EXPECT_LE(entry["error"].get<double>(), 0.25) << entry;
        if (entry["light"] == "spot_light") spotSlots.push_back(entry["slot"]);
    }
    EXPECT_EQ(spotSlots, (std::vector<int>{0, 2}));
    // An output for "spot_light" would be ambiguous: refused, naming both numbers.
    const CommandResult ambiguous = render("--shadow-mask spot_light=" + (dir_ / "mask.png").string());
    EXPECT_EQ(ambiguous.exitCode, 1);
    EXPECT_NE(ambiguous.output.find("names 2 light instances (numbers 1, 3)"), std::string::npos) << ambiguous.output;
    const CommandResult byNumber = render("--shadow-mask 3=" + (dir_ / "mask.png").string());
    EXPECT_EQ(byNumber.exitCode, 0) << byNumber.output;
}

// A scene without lights renders ambient only: said once, with the option that adds a light.
TEST_F(EngineRenderShadows, ASceneWithoutLightsSaysSo) {
    scene_["extensions"].erase("KHR_lights_punctual");
    scene_.erase("extensionsUsed");
    for (auto& node : scene_["nodes"]) node.erase("extensions");
    const CommandResult result = render();
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("the scene has no lights: ambient only, no shadows (--key-light"), std::string::npos)
        << result.output;
    const CommandResult lit = render("--key-light spot");
    EXPECT_EQ(lit.output.find("has no lights"), std::string::npos) << lit.output;
}

TEST_F(EngineRenderShadows, UnnamedLightsOnUnnamedNodesAreEachShadowed) {
    for (auto& entry : scene_["extensions"]["KHR_lights_punctual"]["lights"]) entry.erase("name");
    for (auto& node : scene_["nodes"])
        if (node.contains("extensions")) node.erase("name");  // the lights' nodes
    const CommandResult result = render("--truth");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["lights"].size(), 3u) << all.dump();
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(all["lights"][i]["light"], "light " + std::to_string(i + 1));
        EXPECT_GT(all["lights"][i]["evaluated_pixels"].get<int>(), 100) << all["lights"][i];
    }
}

// After a warm-up frame a still light's map is served from the cache in every timed frame:
// reported as cached (null time), not as a map that took 0.00 ms.
// A light of intensity 0 shadows nothing: --truth says so instead of scoring its all-lit mask
// against the shadows the truth traces (which read as a leak of several percent).
TEST_F(EngineRenderShadows, TruthDoesNotScoreALightThatEmitsNothing) {
    light("sun")["intensity"] = 0.0;
    const CommandResult result = render("--truth");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("not scored: the light emits nothing"), std::string::npos) << result.output;
    std::vector<std::string> scored;
    const nlohmann::json all = stats();  // kept: a range-for over stats()[...] would dangle
    for (const auto& entry : all["lights"]) scored.push_back(entry["light"]);
    EXPECT_EQ(scored, (std::vector<std::string>{"spot_light", "point_light"}));
}

// A light with a size is scored against the soft truth as well, whatever its filter: the
// hard pcf shadow of a sized light disagrees with the truth's penumbra, and its ordinary
// (point-light) score is the same as without the size, since the size does not change a hard
// filter's shadow.
TEST_F(EngineRenderShadows, TruthScoresASizedLightAgainstItsSizeToo) {
    const CommandResult point = render("--truth");
    ASSERT_EQ(point.exitCode, 0) << point.output;
    const nlohmann::json pointStats = stats();
    const CommandResult sized =
        render("--truth --light-set sun.angular_diameter=0.05 --light-set spot_light.light_radius=0.3");
    ASSERT_EQ(sized.exitCode, 0) << sized.output;
    const nlohmann::json sizedStats = stats();
    ASSERT_EQ(sizedStats["lights"].size(), 3u) << sizedStats.dump();
    for (std::size_t i = 0; i < 3; ++i) {
        const nlohmann::json& entry = sizedStats["lights"][i];
        SCOPED_TRACE(entry.dump());
        EXPECT_EQ(entry["error"], pointStats["lights"][i]["error"]);
        EXPECT_FALSE(pointStats["lights"][i].contains("soft_error"));
        if (entry["light"] == "point_light") {
            EXPECT_FALSE(entry.contains("soft_error"));
            continue;
        }
        EXPECT_GT(entry["penumbra_pixels"].get<int>(), 0);
        EXPECT_GT(entry["penumbra_error"].get<double>(), 0.0);
        EXPECT_GT(entry["soft_error"].get<double>(), 0.0);
    }
    EXPECT_NE(sized.output.find("against its size (angular_diameter 0.05)"), std::string::npos) << sized.output;
    EXPECT_NE(sized.output.find("against its size (light_radius 0.3)"), std::string::npos) << sized.output;
}

// The sizes the soft-shadow tests give the showcase's lights (and the masked scenes', which
// have the same three).
constexpr const char* kShowcaseSizes = "--light-set sun.angular_diameter=0.05 --light-set spot_light.light_radius=0.15 "
                                       "--light-set point_light.light_radius=0.1";

// pcss against the area truth of every light type on the showcase (sun 0.05 rad, spot r 0.15,
// point r 0.1, 480x270), beside pcf on the same sized lights in the same run. Measured on
// llvmpipe, soft error / penumbra error pcf -> pcss: spot 0.320 / 20.7 % -> 0.084 / 4.7 %,
// sun 0.105 / 18.9 % -> 0.038 / 5.6 %, point 0.910 / 22.7 % -> 0.253 / 5.8 %. Bounds (the
// issue's targets): soft error at most half of pcf's (measured at most 0.36x), penumbra
// error at most half of pcf's (measured at most 0.30x) and at most 12 % (measured at most
// 5.8 %).
TEST_F(EngineRenderShadows, PcssAndWidePcfFollowTheAreaTruthOfEverySizedLight) {
    const nlohmann::json pcf = everyLightWith(kShowcaseSizes), pcss = everyLightWith(kShowcaseSizes, "filter", "pcss");
    ASSERT_FALSE(pcf.is_null() || pcss.is_null());
    for (std::size_t i = 0; i < 3; ++i) {
        const nlohmann::json& measured = pcss[i];
        const nlohmann::json& control = pcf[i];
        SCOPED_TRACE(measured.dump() + "\n" + control.dump());
        EXPECT_GT(measured["penumbra_pixels"].get<int>(), 500);
        EXPECT_LE(measured["soft_error"].get<double>(), 0.5 * control["soft_error"].get<double>());
        EXPECT_LE(measured["penumbra_error"].get<double>(), 0.5 * control["penumbra_error"].get<double>());
        EXPECT_LE(measured["penumbra_error"].get<double>(), 12.0);
    }
    // Wide pcf (filter_radius 4 texels) buys softer edges without pcss: penumbra error at most
    // 0.85x the one tap's (measured 9.8 / 11.9 / 17.1 % against 20.7 / 18.9 / 22.7 %: at most
    // 0.75x, the point light's, whose cube texels are the widest).
    const nlohmann::json widePcf = everyLightWith(kShowcaseSizes, "filter_radius", "4");
    ASSERT_FALSE(widePcf.is_null());
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(widePcf[i].dump());
        EXPECT_LE(widePcf[i]["penumbra_error"].get<double>(), 0.85 * pcf[i]["penumbra_error"].get<double>());
    }
}

// Small lights (the real sun's 0.0093 rad; bulbs of 2 cm): their penumbrae are under a
// texel, and pcss must then shade like the 2x2 filter, not blur a texel's width around every
// edge. Measured soft error pcf -> pcss: spot 0.049 -> 0.045 %, sun 0.037 -> 0.031 %, point
// 0.152 -> 0.069 % (with the filter held at least a texel wide: 0.073, 0.068, 0.132 %, up to
// 1.8x pcf's). Bound: pcss at most 1.05x pcf's (measured at most 0.92x).
TEST_F(EngineRenderShadows, PcssShadesSmallLightsAtLeastAsWellAsTheHardFilter) {
    const std::string small = "--light-set sun.angular_diameter=0.0093 --light-set spot_light.light_radius=0.02 "
                              "--light-set point_light.light_radius=0.02";
    const nlohmann::json pcf = everyLightWith(small), pcss = everyLightWith(small, "filter", "pcss");
    ASSERT_FALSE(pcf.is_null() || pcss.is_null());
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(pcss[i].dump() + "\n" + pcf[i].dump());
        EXPECT_LE(pcss[i]["soft_error"].get<double>(), 1.05 * pcf[i]["soft_error"].get<double>());
    }
}

// pcss through alpha-masked casters: the canopy's leaves are masked quads, and the truth
// traces their masks (tools/truth), so pcss's soft shade is judged on the holes' own
// penumbrae. Same sizes and size as above. Measured soft error / penumbra error pcf -> pcss:
// spot 3.03 / 23.0 % -> 0.563 / 4.2 %, sun 1.42 / 20.5 % -> 0.295 / 4.0 %, point 5.30 /
// 22.9 % -> 1.11 / 4.6 %. Bounds: soft error at most half of pcf's (measured at most
// 0.21x), penumbra error at most 12 % (the issue's target; measured at most 4.6 %).
TEST_F(EngineRenderShadows, PcssFollowsTheAreaTruthThroughAlphaMaskedCasters) {
    useScene("masked_canopy");
    const nlohmann::json pcf = everyLightWith(kShowcaseSizes), pcss = everyLightWith(kShowcaseSizes, "filter", "pcss");
    ASSERT_FALSE(pcf.is_null() || pcss.is_null());
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(pcss[i].dump() + "\n" + pcf[i].dump());
        EXPECT_GT(pcss[i]["penumbra_pixels"].get<int>(), 5000);  // measured at least 8694
        EXPECT_LE(pcss[i]["soft_error"].get<double>(), 0.5 * pcf[i]["soft_error"].get<double>());
        EXPECT_LE(pcss[i]["penumbra_error"].get<double>(), 12.0);
    }
}

TEST_F(EngineRenderShadows, TruthReportsACachedMapAsCached) {
    const CommandResult result = render("--truth --warmup 1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["lights"].size(), 3u) << all.dump();
    for (const auto& entry : all["lights"]) {
        EXPECT_TRUE(entry["map_cached"].get<bool>()) << entry;
        EXPECT_TRUE(entry["map_ms"].is_null()) << entry;
    }
    EXPECT_NE(result.output.find("cached"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(" 0.00 "), std::string::npos) << result.output;
}

// Accuracy guards against ray-traced truth (errors, never timings): the showcase at 320x180
// with every light's map at 2048 under each variant. Bounds: error <= 0.25 % and error off
// truth edges <= 0.06 % of the evaluation set; measured on llvmpipe: at most 0.133 % and
// 0.031 % (woo), so a regression that adds acne or leak on surfaces fails here.
TEST_F(EngineRenderShadows, EveryVariantStaysWithinItsErrorBoundAt2048) {
    for (const char* name : {"spot_light", "sun", "point_light"}) light(name)["extras"]["shadow"]["resolution"] = 2048;
    for (const std::string variant : {"standard", "woo", "backface"}) {
        const CommandResult result =
            render("--width 320 --height 180 --truth --light spot_light=" + variant + " --light sun=" + variant +
                   " --light point_light=" + variant);
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const nlohmann::json all = stats();
        ASSERT_EQ(all["lights"].size(), 3u);
        for (const auto& entry : all["lights"]) {
            EXPECT_EQ(entry["variant"], variant);
            EXPECT_GT(entry["evaluated_pixels"].get<int>(), 2000) << entry;
            EXPECT_LE(entry["error"].get<double>(), 0.25) << variant << " " << entry;
            EXPECT_LE(entry["error_noedge"].get<double>(), 0.06) << variant << " " << entry;
        }
    }
}

// Shadow volumes on the showcase: exact at pixel centres, so their error against ray-traced
// truth (edges included) is far below any map's. Measured at 320x180: spot 0.012 %, sun
// 0.003 %, point 0.018 % (pixels whose centre lies within rounding of a shadow edge), off edges
// 0.000 %; the bounds, 0.05 % and 0.01 %, are under the best map's 0.046 % at 480x270.
TEST_F(EngineRenderShadows, VolumesAreExactOnEveryShowcaseLight) {
    const CommandResult result =
        render("--width 320 --height 180 --truth --light spot_light=volume --light sun=volume --light point_light=volume");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["lights"].size(), 3u);
    for (const auto& entry : all["lights"]) {
        EXPECT_EQ(entry["variant"], "volume");
        EXPECT_GT(entry["evaluated_pixels"].get<int>(), 2000) << entry;
        EXPECT_LE(entry["error"].get<double>(), 0.05) << entry;
        EXPECT_LE(entry["error_noedge"].get<double>(), 0.01) << entry;
    }
}

// An alpha-tested caster cannot be a volume (a volume has no texture to test): a volume light
// among such casters warns once, naming the material, and shadows with a standard map, so its
// error is the standard variant's to the last digit.
TEST_F(EngineRenderShadows, AVolumeLightAmongAlphaTestedCastersFallsBackToAStandardMap) {
    useScene("masked_fence");
    const CommandResult standard = render("--width 160 --height 90 --truth --light spot_light=standard");
    ASSERT_EQ(standard.exitCode, 0) << standard.output;
    const nlohmann::json expected = stats()["lights"];
    const CommandResult volume = render("--width 160 --height 90 --truth --light spot_light=volume");
    ASSERT_EQ(volume.exitCode, 0) << volume.output;
    const std::string warning = "alpha-tested material \"fence_masked\" cannot cast a shadow volume";
    const std::size_t at = volume.output.find(warning);
    EXPECT_NE(at, std::string::npos) << volume.output;
    EXPECT_EQ(volume.output.find(warning, at + 1), std::string::npos) << "said more than once: " << volume.output;
    const nlohmann::json lights = stats()["lights"];
    ASSERT_EQ(lights.size(), expected.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights[i]["light"] != "spot_light") continue;
        EXPECT_EQ(lights[i]["variant"], "standard") << lights[i];
        EXPECT_EQ(lights[i]["error"], expected[i]["error"]) << lights[i] << "\n" << expected[i];
        EXPECT_EQ(lights[i]["evaluated_pixels"], expected[i]["evaluated_pixels"]);
    }
}

// cascades 1 is the one fitted map the plugin drew before cascades existed, and on the
// showcase the default (auto) chooses it: both render the very same bytes, made in one run
// on one CPU, so the guard holds on any machine. (A stored image cannot be this guard across
// CPUs: an Intel Xeon's llvmpipe rendered 436 of its 57,600 bytes differently from the AMD
// machine that stored it, while real changes of the sun's map -- 2 cascades, or 2040 texels
// instead of 2048 -- changed only 90 and 55 bytes at this size.) What the one map should
// render is the truth's to say: the sun's error at 160x90 measured 0.077 % of 9,578 evaluated
// pixels (one pixel is 0.010 %); the bound, 0.15 %, leaves seven pixels of margin.
TEST_F(EngineRenderShadows, OneCascadeIsTheMapTheDefaultChoosesOnTheShowcase) {
    std::vector<unsigned char> images[2];
    const std::string settings[2] = {"", " --light-set sun.cascades=1"};
    for (int i = 0; i < 2; ++i) {
        const fs::path stats = dir_ / ("stats" + std::to_string(i) + ".json");
        const CommandResult result =
            runEngineRender("--config " + std::string(CONTENT_DIR) + "/engine.json --scene " + CONTENT_DIR +
                            "/scenes/showcase.gltf --out " + (dir_ / "out.png").string() +
                            " --width 160 --height 90 --warmup 0 --truth --stats " + stats.string() + settings[i]);
        ASSERT_EQ(result.exitCode, 0) << result.output;
        int width = 0, height = 0;
        images[i] = engine::readPng(dir_ / "out.png", 4, width, height);
        ASSERT_EQ(images[i].size(), 160u * 90u * 4u);
        std::ifstream in(stats);
        const nlohmann::json all = nlohmann::json::parse(in);
        bool sunSeen = false;
        for (const auto& entry : all["lights"]) {
            if (entry["light"] != "sun") continue;
            sunSeen = true;
            EXPECT_GT(entry["evaluated_pixels"].get<int>(), 9000) << entry;
            EXPECT_LE(entry["error"].get<double>(), 0.15) << settings[i] << " " << entry;
        }
        EXPECT_TRUE(sunSeen) << all.dump();
        for (const auto& entry : all["plugins"]["shadowmap_plugin"]["lights"]) {
            if (entry["light"] != "sun") continue;
            EXPECT_EQ(entry["map"], "2d") << settings[i] << " " << entry;
        }
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i < images[0].size(); ++i) differing += images[0][i] != images[1][i];
    EXPECT_EQ(differing, 0u) << "bytes differing between the default (auto) and cascades 1";
}

// woo with an explicit polygon_offset: both of its passes take the offset, so the peel still
// recognises the nearest surface. With the offset in the peel pass alone the sun's error at
// 512 texels with [1, 2] was 14.8 % at this size (measured); with it in both, 0.130 %,
// below the 0.258 % of no offset. Bound: no worse than without the offset, give or take one
// evaluated pixel (100 / |E| percent), the metric's own resolution.
TEST_F(EngineRenderShadows, WooWithAnExplicitOffsetIsNoWorseThanWithout) {
    light("sun")["extras"]["shadow"]["variant"] = "woo";
    light("sun")["extras"]["shadow"]["resolution"] = 512;
    const auto sunErrors = [&] {
        const CommandResult result = render("--width 320 --height 180 --truth");
        EXPECT_EQ(result.exitCode, 0) << result.output;
        const nlohmann::json all = stats();
        for (const auto& entry : all["lights"])
            if (entry["light"] == "sun") return entry;
        ADD_FAILURE() << "no truth for the sun in " << all.dump();
        return nlohmann::json();
    };
    const nlohmann::json without = sunErrors();
    light("sun")["extras"]["shadow"]["polygon_offset"] = {1.0, 2.0};
    const nlohmann::json with = sunErrors();
    ASSERT_FALSE(without.is_null() || with.is_null());
    ASSERT_EQ(with["variant"], "woo");
    const double onePixel = 100.0 / with["evaluated_pixels"].get<double>();
    EXPECT_LE(with["error"].get<double>(), without["error"].get<double>() + onePixel) << with << "\n" << without;
    EXPECT_LE(with["acne"].get<double>(), without["acne"].get<double>() + onePixel) << with << "\n" << without;
}

// --stats' shadow_maps (from the published shadow views, not pass names): an orbiting light's
// map is redrawn and timed every frame, a still light's is served from the cache.
TEST_F(EngineRenderShadows, StatsGiveEveryLightsMapTimeOrSayItWasCached) {
    const CommandResult result = render("--warmup 1 --frames 2 --orbit-light sun");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    ASSERT_EQ(all["shadow_maps"].size(), 3u) << all.dump();
    for (const auto& entry : all["shadow_maps"]) {
        const bool orbiting = entry["light"] == "sun";
        EXPECT_EQ(entry["map_cached"].get<bool>(), !orbiting) << entry;
        if (orbiting) EXPECT_GT(entry["map_ms"].get<double>(), 0.0) << entry;
        else EXPECT_TRUE(entry["map_ms"].is_null()) << entry;
    }
    EXPECT_EQ(all["shadow_maps"][1]["map"], "2d");
    EXPECT_EQ(all["shadow_maps"][2]["map"], "cube");
}

// ---- Command-line overrides: never silently nothing --------------------------------------

namespace {

// How often `fragment` occurs in `text`.
int occurrences(const std::string& text, const std::string& fragment) {
    int count = 0;
    for (auto at = text.find(fragment); at != std::string::npos; at = text.find(fragment, at + 1)) ++count;
    return count;
}

} // namespace

// --set edits the config, which a light's extras override: each light whose extras set the
// key is named once, with the value that wins and the per-light option that would not lose.
TEST_F(EngineRenderShadows, ASetShadowedByALightsExtrasWarnsNamingTheLightAndTheKey) {
    light("spot_light")["extras"]["shadow"].erase("resolution");  // silent: the --set applies
    const CommandResult result = render("--set shadowmap_plugin.resolution=512");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(occurrences(result.output, "does nothing for light \"sun\": its glTF extras set resolution to 2048"), 1)
        << result.output;
    EXPECT_EQ(occurrences(result.output, "--light-set sun.resolution=512"), 1) << result.output;
    EXPECT_EQ(occurrences(result.output, "does nothing for light \"point_light\": its glTF extras set resolution "
                                         "to 1024"), 1) << result.output;
    EXPECT_EQ(result.output.find("does nothing for light \"spot_light\""), std::string::npos) << result.output;
    EXPECT_EQ(pluginLightStats("spot_light")["resolution"], 512);
    EXPECT_EQ(pluginLightStats("sun")["resolution"], 2048);
    // A per-light option for that key settles it: no warning for that light.
    const CommandResult settled = render("--set shadowmap_plugin.resolution=512 --light-set sun.resolution=256");
    ASSERT_EQ(settled.exitCode, 0) << settled.output;
    EXPECT_EQ(settled.output.find("light \"sun\": its glTF extras"), std::string::npos) << settled.output;
    EXPECT_NE(settled.output.find("light \"point_light\": its glTF extras"), std::string::npos) << settled.output;
}

// --light-set wins over the extras: the light's map is made at the size asked for (stats and
// the map written by --shadow-map), the other lights keep theirs; a light is named by name
// or by its number in --list.
TEST_F(EngineRenderShadows, LightSetChangesThatLightsMap) {
    const CommandResult result = render("--light-set sun.resolution=512 --light-set 3.filter=nearest "
                                        "--light-set spot_light.polygon_offset=[3,16] --shadow-map sun=" +
                                        (dir_ / "sun.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(pluginLightStats("sun")["resolution"], 512);
    EXPECT_EQ(pluginLightStats("spot_light")["resolution"], 2048);
    EXPECT_EQ(pluginLightStats("point_light")["filter"], "nearest");
    EXPECT_EQ(pluginLightStats("sun")["filter"], "pcf");
    EXPECT_EQ(pluginLightStats("spot_light")["polygon_offset"], nlohmann::json::array({3.0, 16.0}));
    int width = 0, height = 0;
    engine::readPng(dir_ / "sun.png", 1, width, height);
    EXPECT_EQ(width, 512);
    EXPECT_EQ(height, 512);
}

TEST_F(EngineRenderShadows, BadLightSetNamesTheLightTheKeyAndTheReason) {
    expectError(render("--light-set sun.resolution=0"),
                {"--light-set sun.resolution=0", "light \"sun\".resolution", "whole number of texels >= 1, got 0"});
    expectError(render("--light-set 2.bias=0.1"), {"--light-set 2.bias=0.1", "light \"sun\".bias", "unknown key"});
    expectError(render("--light-set sun.filter=[1]"), {"light \"sun\".filter", "must be a string"});
    // Checked with the light's other settings: its extras say d24.
    expectError(render("--light-set sun.reversed_z=true"), {"light \"sun\".reversed_z", "needs depth_format \"d32f\""});
    expectError(render("--light-set nosuchlight.resolution=512"), {"light \"nosuchlight\"", "no such light"});
    expectError(render("--light-set sun=512"), {"--light-set", "must be NAME.KEY=VALUE"});
    expectError(render("--light-set sun.light_radius=0.5"),
                {"light \"sun\".light_radius", "a directional light has no radius: size it with angular_diameter"});
    expectError(render("--light-set sun.angular_diameter=-0.01"),
                {"light \"sun\".angular_diameter", "must be >= 0 radians"});
}

// A size on the other type of light, in the file: named with the scene, light and key.
TEST_F(EngineRenderShadows, ASizeOnTheWrongTypeOfLightInTheFileIsNamed) {
    light("spot_light")["extras"]["shadow"]["angular_diameter"] = 0.01;
    expectError(render(), {"light \"spot_light\": extras.shadow.angular_diameter",
                           "a spot or point light has no angular diameter: size it with light_radius"});
}

// The last of two values winning silently hid typos in scripts: both are named instead.
TEST_F(EngineRenderShadows, ARepeatedOverrideIsAnErrorNamingBothValues) {
    expectError(render("--light sun=woo --light sun=backface"), {"\"woo\" and \"backface\"", "light \"sun\".variant"});
    // The same light typed two ways, and --light against --light-set.
    expectError(render("--light sun=woo --light-set 2.variant=backface"), {"\"woo\" and \"backface\""});
    expectError(render("--set shadowmap_plugin.resolution=512 --set shadowmap_plugin.resolution=1024"),
                {"shadowmap_plugin.resolution is given twice: 512 and 1024"});
}

// One name, the one users type in the config: in --stats, --set and the plugin's messages.
TEST_F(EngineRenderShadows, ThePluginIsCalledShadowmapPluginEverywhere) {
    light("sun")["extras"]["shadow"]["near_plane"] = 1.0;  // a directional light ignores it, with a warning
    const CommandResult result = render("--set shadowmap_plugin.cache_maps=false");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json all = stats();
    EXPECT_TRUE(all["plugins"].contains("shadowmap_plugin")) << all["plugins"].dump();
    EXPECT_FALSE(all["plugins"].contains("shadowmap")) << all["plugins"].dump();
    EXPECT_EQ(all["plugins"]["shadowmap_plugin"]["cache_maps"], false);
    EXPECT_NE(result.output.find("warning: shadowmap_plugin: "), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("warning: shadowmap: "), std::string::npos) << result.output;
    fs::remove(dir_ / "out.png");  // the refused run below must write none
    expectError(render("--set shadowmap.cache_maps=false"),
                {"loads no plugin \"shadowmap\" (it loads: shadowmap_plugin)"});
}

// A point light's cube faces are axis-aligned: a surface facing a face's axis has zero depth
// slope there, so the polygon offset's slope term gives it no margin, and a small step in it
// (2CylinderEngine's crankcase top under the key point light) drew a dotted acne line
// until the cube lookup got a texel bias of its own (technique/projection/CubeMapProjection.cpp, kCubeTexelBias).
// Measured at this size: acne 1.230% without the bias, 1.001% with it (leak 0.245% and
// 0.253%); the bound sits between, 0.1 points above what the fix gives.
TEST(EngineRenderCubeAcne, AFloorFacingACubeFaceGetsATexelBias) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    const fs::path dir = fs::temp_directory_path() / "engine_render_cube_acne";
    fs::create_directories(dir);
    const CommandResult result = runEngineRender(
        "--config " + std::string(CONTENT_DIR) + "/engine.json --scene " +
        (engine::test::kAssimpGltf2Models / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb").string() +
        " --key-light point --truth --width 320 --height 180 --out " + (dir / "out.png").string() + " --stats " +
        (dir / "stats.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream in(dir / "stats.json");
    const nlohmann::json light = nlohmann::json::parse(in)["lights"].at(0);
    EXPECT_LT(light["acne"].get<double>(), 1.1) << light;
    EXPECT_LT(light["leak"].get<double>(), 0.3) << light;  // measured 0.253: the bias adds little leak
    fs::remove_all(dir);
}

// cascades on a spot or point light would be silently nothing: it is said, once per light.
TEST_F(EngineRenderShadows, CascadesOnAPointOrSpotLightAreIgnoredWithAWarning) {
    const CommandResult result =
        render("--frames 2 --light-set spot_light.cascades=3 --light-set point_light.cascades=2");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(occurrences(result.output, "light \"spot_light\": cascades apply to directional lights only: 3 ignored"), 1)
        << result.output;
    EXPECT_EQ(occurrences(result.output, "light \"point_light\": cascades apply to directional lights only: 2 ignored"), 1)
        << result.output;
}

// --truth-mask writes the truth --truth scores the light against, lined up with its
// --shadow-mask: the mean |mask - truth| recomputed from the two PNGs over the pixels the
// truth mask does not leave as background is the soft error the stats report. The two sets
// differ: the stats' evaluation set also holds the truth's umbra (0, written like the
// background), here about a tenth of it (591 of 6488 px). Measured at 160x90: 0.1057 % from
// the PNGs against 0.1069 % in the stats (1.1 % apart); the bound, 10 % of the stats' figure,
// is that umbra share, which is how far the two means part if all the error lies outside the
// umbra. Checked to fail: a truth mask written binarised (the hard truth) is off by more.
TEST_F(EngineRenderShadows, TruthMaskIsTheTruthTheSoftErrorIsMeasuredAgainst) {
    const std::string sized = "--width 160 --height 90 --light-set spot_light.light_radius=0.15 "
                              "--light-set spot_light.filter=pcss ";
    const CommandResult result = render(sized + "--shadow-mask spot_light=" + (dir_ / "mask.png").string() +
                                        " --truth-mask spot_light=" + (dir_ / "truth.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json light = stats()["lights"].at(0);  // --truth-mask implies --truth
    ASSERT_EQ(light["light"], "spot_light") << light;
    const double softError = light.at("soft_error").get<double>();
    ASSERT_GT(softError, 0.0) << "nothing to compare: " << light;

    int width = 0, height = 0;
    const std::vector<std::uint8_t> mask = engine::readPng(dir_ / "mask.png", 1, width, height);
    const std::vector<std::uint8_t> truth = engine::readPng(dir_ / "truth.png", 1, width, height);
    ASSERT_EQ(width * height, 160 * 90);
    ASSERT_EQ(mask.size(), truth.size());
    double sum = 0.0;
    std::size_t scored = 0;
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (truth[i] != 0) {
            const int difference = int(mask[i]) - int(truth[i]);
            sum += (difference < 0 ? -difference : difference) / 255.0;
            ++scored;
        }
    ASSERT_GT(scored, 0u);
    EXPECT_NEAR(100.0 * sum / double(scored), softError, 0.1 * softError) << light;

    fs::remove(dir_ / "out.png");  // the refused runs below must write none
    expectError(render(sized + "--truth-mask nosuch=" + (dir_ / "t.png").string()),
                {"light \"nosuch\": no such light"});
    expectError(render(sized + "--truth-mask spot_light=" + (dir_ / "missing" / "t.png").string()),
                {"t.png: its folder", "missing does not exist"});
}
