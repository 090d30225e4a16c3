// Engine config parsing: valid configs, and bad ones with messages naming file and key.
#include "engine/config/EngineConfig.h"
#include "engine/util/Error.h"

#include <gtest/gtest.h>

namespace {

std::string configError(const std::string& text) {
    try {
        engine::parseEngineConfig(text, "my/engine.json");
    } catch (const engine::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "accepted: " << text;
    return {};
}

} // namespace

TEST(EngineConfig, ParsesPluginsSettingsAndRenderer) {
    const auto config = engine::parseEngineConfig(
        R"({"plugin_dirs":["plugins"],"plugins":[{"library":"shadowmap_plugin",
            "settings":{"variant":"woo","resolution":1024}}],
            "renderer":{"ambient":[0.1,0.2,0.3],"shade_cache":false,"light_footprints":false,"unrolled_light_sum":false,
                        "check_gl_errors":true,"exposure":2.5e-5,"tone_mapping":"pbr_neutral"}})",
        "my/engine.json");
    ASSERT_EQ(config.plugins.size(), 1u);
    EXPECT_EQ(config.plugins[0].library, "shadowmap_plugin");
    EXPECT_EQ(config.plugins[0].settings["resolution"], 1024);
    ASSERT_EQ(config.pluginDirs.size(), 1u);
    EXPECT_EQ(config.pluginDirs[0], std::filesystem::path("my/plugins"));
    EXPECT_FLOAT_EQ(config.renderer.ambient.y, 0.2f);
    EXPECT_EQ(config.renderer.shadeCache, std::optional<bool>(false));
    EXPECT_EQ(config.renderer.lightFootprints, std::optional<bool>(false));
    EXPECT_TRUE(config.renderer.checkGlErrors);
    EXPECT_EQ(config.renderer.unrolledLightSum, std::optional<bool>(false));
    EXPECT_FLOAT_EQ(config.renderer.exposure, 2.5e-5f);
    EXPECT_EQ(config.renderer.toneMapping, engine::RendererConfig::ToneMapping::PbrNeutral);
    EXPECT_EQ(engine::parseEngineConfig("{}", "my/engine.json").renderer.exposure, 1.0f);
    EXPECT_EQ(engine::parseEngineConfig("{}", "my/engine.json").renderer.toneMapping,
              engine::RendererConfig::ToneMapping::None);
    // Left out, the llvmpipe switches are unset: decided for the renderer (decideSwitches).
    const engine::RendererConfig defaults = engine::parseEngineConfig("{}", "my/engine.json").renderer;
    EXPECT_FALSE(defaults.shadeCache.has_value());
    EXPECT_FALSE(defaults.lightFootprints.has_value());
    EXPECT_FALSE(defaults.unrolledLightSum.has_value());
}

TEST(EngineConfig, SwitchesAreTrueFalseOrAuto) {
    const engine::RendererConfig renderer = engine::parseEngineConfig(
        R"({"renderer":{"shade_cache":true,"light_footprints":"auto","unrolled_light_sum":false}})", "my/engine.json")
        .renderer;
    EXPECT_EQ(renderer.shadeCache, std::optional<bool>(true));
    EXPECT_FALSE(renderer.lightFootprints.has_value());
    EXPECT_EQ(renderer.unrolledLightSum, std::optional<bool>(false));
    EXPECT_NE(configError(R"({"renderer":{"shade_cache":"on"}})")
                  .find("my/engine.json: renderer.shade_cache: must be true, false or \"auto\", not \"on\""),
              std::string::npos)
        << configError(R"({"renderer":{"shade_cache":"on"}})");
    EXPECT_NE(configError(R"({"renderer":{"light_footprints":1}})").find("renderer.light_footprints: must be"),
              std::string::npos);
}

// Unset switches follow the renderer: on for Mesa's software rasterizers, off on a GPU;
// a switch the config sets is kept on either.
TEST(EngineConfig, UnsetSwitchesAreOnForSoftwareRasterizersOffOnGpus) {
    EXPECT_TRUE(engine::isSoftwareRasterizer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(engine::isSoftwareRasterizer("softpipe"));
    EXPECT_FALSE(engine::isSoftwareRasterizer("NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(engine::isSoftwareRasterizer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)"));
    EXPECT_FALSE(engine::isSoftwareRasterizer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));

    engine::RendererConfig config;
    const engine::RendererSwitches software = engine::decideSwitches(config, "llvmpipe (LLVM 15.0.6, 256 bits)");
    EXPECT_TRUE(software.shadeCache && software.lightFootprints && software.unrolledLightSum);
    const engine::RendererSwitches gpu = engine::decideSwitches(config, "NVIDIA H200/PCIe/SSE2");
    EXPECT_FALSE(gpu.shadeCache || gpu.lightFootprints || gpu.unrolledLightSum);

    config.shadeCache = true;
    config.unrolledLightSum = false;
    const engine::RendererSwitches forcedOnGpu = engine::decideSwitches(config, "NVIDIA H200/PCIe/SSE2");
    EXPECT_TRUE(forcedOnGpu.shadeCache);
    EXPECT_FALSE(forcedOnGpu.lightFootprints);
    const engine::RendererSwitches forcedOnSoftware = engine::decideSwitches(config, "llvmpipe");
    EXPECT_FALSE(forcedOnSoftware.unrolledLightSum);
    EXPECT_TRUE(forcedOnSoftware.lightFootprints);
}

TEST(EngineConfig, BadInputNamesFileAndKey) {
    EXPECT_NE(configError("{").find("my/engine.json: not valid JSON"), std::string::npos);
    EXPECT_NE(configError(R"({"plugnis":[]})").find("plugnis: unknown key"), std::string::npos);
    EXPECT_NE(configError(R"({"plugins":[{"settings":{}}]})").find("plugins[0]: missing \"library\""),
              std::string::npos);
    EXPECT_NE(configError(R"({"plugins":[{"library":"../evil"}]})").find("plugins[0].library"),
              std::string::npos);
    EXPECT_NE(configError(R"({"plugins":[{"library":"x","settings":3}]})")
                  .find("plugins[0].settings: must be a JSON object"),
              std::string::npos);
    EXPECT_NE(configError(R"({"renderer":{"ambient":[1,2]}})").find("renderer.ambient"),
              std::string::npos);
    EXPECT_NE(configError(R"({"renderer":{"shade_cache":"yes"}})").find("renderer.shade_cache"),
              std::string::npos);
    EXPECT_NE(configError(R"({"renderer":{"light_footprints":"on"}})").find("renderer.light_footprints"),
              std::string::npos);
    EXPECT_NE(configError(R"({"renderer":{"unrolled_light_sum":0}})").find("renderer.unrolled_light_sum"),
              std::string::npos);
    EXPECT_NE(configError(R"({"renderer":{"check_gl_errors":1}})").find("renderer.check_gl_errors"),
              std::string::npos);
    for (const char* exposure : {"0", "-1", "\"1\"", "1e31"})
        EXPECT_NE(configError(std::string(R"({"renderer":{"exposure":)") + exposure + "}}").find("renderer.exposure"),
                  std::string::npos)
            << exposure;
    EXPECT_NE(configError(R"({"renderer":{"tone_mapping":"aces"}})").find("renderer.tone_mapping: \"aces\" is not"),
              std::string::npos);
}

TEST(EngineConfig, MsaaIsOneTwoFourOrEight) {
    // Left out: 1, today's single-sampled image.
    EXPECT_EQ(engine::parseEngineConfig("{}", "my/engine.json").renderer.msaa, 1);
    for (const int samples : engine::kMsaaSampleCounts)
        EXPECT_EQ(engine::parseEngineConfig(R"({"renderer":{"msaa":)" + std::to_string(samples) + "}}", "my/engine.json")
                      .renderer.msaa,
                  samples);
    for (const char* samples : {"0", "3", "16", "-4", "4.0", "\"4\"", "true", "4294967300"}) {
        const std::string message = configError(std::string(R"({"renderer":{"msaa":)") + samples + "}}");
        EXPECT_NE(message.find("my/engine.json: renderer.msaa: must be 1, 2, 4 or 8"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    // The shade cache cannot serve a multisampled image: asked for both, the config says so;
    // left to "auto", multisampling turns it off, whatever the renderer.
    const std::string both = configError(R"({"renderer":{"msaa":4,"shade_cache":true}})");
    EXPECT_NE(both.find("renderer.shade_cache: true needs renderer.msaa 1"), std::string::npos) << both;
    engine::RendererConfig multisampled;
    multisampled.msaa = 4;
    EXPECT_FALSE(engine::decideSwitches(multisampled, "llvmpipe (LLVM 15.0.6, 256 bits)").shadeCache);
    EXPECT_TRUE(engine::decideSwitches(engine::RendererConfig{}, "llvmpipe (LLVM 15.0.6, 256 bits)").shadeCache);
}
