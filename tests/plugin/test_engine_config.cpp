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
    EXPECT_FALSE(config.renderer.shadeCache);
    EXPECT_FALSE(config.renderer.lightFootprints);
    EXPECT_TRUE(config.renderer.checkGlErrors);
    EXPECT_FALSE(config.renderer.unrolledLightSum);
    EXPECT_FLOAT_EQ(config.renderer.exposure, 2.5e-5f);
    EXPECT_EQ(config.renderer.toneMapping, engine::RendererConfig::ToneMapping::PbrNeutral);
    EXPECT_EQ(engine::parseEngineConfig("{}", "my/engine.json").renderer.exposure, 1.0f);
    EXPECT_EQ(engine::parseEngineConfig("{}", "my/engine.json").renderer.toneMapping,
              engine::RendererConfig::ToneMapping::None);
    EXPECT_TRUE(engine::parseEngineConfig("{}", "my/engine.json").renderer.shadeCache);
    EXPECT_TRUE(engine::parseEngineConfig("{}", "my/engine.json").renderer.lightFootprints);
    EXPECT_TRUE(engine::parseEngineConfig("{}", "my/engine.json").renderer.unrolledLightSum);
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
