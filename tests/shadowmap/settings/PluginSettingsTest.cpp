// The plugin's config settings through the settings API: the per-light defaults and the
// plugin-wide cache_maps parse together, a bad cache_maps is an error naming its key, and
// the keys accepted are the per-light ones plus cache_maps.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

std::string parseError(const nlohmann::json& json) {
    try {
        shadowmap::parsePluginSettings(json, "engine.json");
    } catch (const engine::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << json.dump() << " parsed";
    return "";
}

} // namespace

TEST(PluginSettings, DefaultsCacheMaps) {
    const shadowmap::PluginSettings settings = shadowmap::parsePluginSettings(nlohmann::json::object(), "engine.json");
    EXPECT_TRUE(settings.cacheMaps);
    EXPECT_EQ(settings.lightDefaults, shadowmap::ShadowSettings{});
}

TEST(PluginSettings, ReadsCacheMapsBesideTheLightDefaults) {
    const shadowmap::PluginSettings settings = shadowmap::parsePluginSettings(
        {{"variant", "woo"}, {"resolution", 512}, {shadowmap::kCacheMapsKey, false}}, "engine.json");
    EXPECT_FALSE(settings.cacheMaps);
    shadowmap::ShadowSettings expected;
    expected.variant = shadowmap::Variant::Woo;
    expected.resolution = 512;
    EXPECT_EQ(settings.lightDefaults, expected);
}

TEST(PluginSettings, RejectsANonBooleanCacheMapsNamingTheKey) {
    EXPECT_EQ(parseError({{"cache_maps", "no"}}), "engine.json: settings.cache_maps: must be true or false");
}

TEST(PluginSettings, RejectsUnknownKeysListingEveryKnownOne) {
    std::string known;
    for (const std::string& key : shadowmap::pluginSettingKeys()) known += (known.empty() ? "" : ", ") + key;
    EXPECT_EQ(parseError({{"colour", "red"}}), "engine.json: settings.colour: unknown key (known: " + known + ")");
}

TEST(PluginSettings, ABadLightDefaultNamesItsKey) {
    EXPECT_NE(parseError({{"dimming", 2}}).find("engine.json: settings.dimming: "), std::string::npos);
}

TEST(PluginSettings, KeysAreTheLightKeysThenThePluginWideOnes) {
    std::vector<std::string> expected;
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) expected.push_back(key.name);
    expected.push_back("cache_maps");
    expected.push_back("volume_extrusion");
    expected.push_back("volume_counting");
    EXPECT_EQ(shadowmap::pluginSettingKeys(), expected);
}

TEST(PluginSettings, VolumeCountingIsAutoUnlessZFailIsAsked) {
    EXPECT_TRUE(shadowmap::parsePluginSettings(nlohmann::json::object(), "engine.json").volumesZPass);
    EXPECT_TRUE(shadowmap::parsePluginSettings({{"volume_counting", "auto"}}, "engine.json").volumesZPass);
    const shadowmap::PluginSettings zFail = shadowmap::parsePluginSettings({{"volume_counting", "z-fail"}}, "engine.json");
    EXPECT_FALSE(zFail.volumesZPass);
    EXPECT_EQ(zFail.lightDefaults, shadowmap::ShadowSettings{});
    EXPECT_EQ(parseError({{"volume_counting", "z-pass"}}),
              "engine.json: settings.volume_counting: unknown value \"z-pass\" (known: auto, z-fail)");
}

TEST(PluginSettings, VolumeExtrusionIsCpuUnlessGpuIsAsked) {
    EXPECT_FALSE(shadowmap::parsePluginSettings(nlohmann::json::object(), "engine.json").volumesOnGpu);
    EXPECT_FALSE(shadowmap::parsePluginSettings({{"volume_extrusion", "cpu"}}, "engine.json").volumesOnGpu);
    const shadowmap::PluginSettings gpu = shadowmap::parsePluginSettings({{"volume_extrusion", "gpu"}}, "engine.json");
    EXPECT_TRUE(gpu.volumesOnGpu);
    EXPECT_EQ(gpu.lightDefaults, shadowmap::ShadowSettings{});
    EXPECT_EQ(parseError({{"volume_extrusion", "gs"}}),
              "engine.json: settings.volume_extrusion: unknown value \"gs\" (known: cpu, gpu)");
}
