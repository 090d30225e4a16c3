// The tools' command-line toolkit: every bad value is refused with one line naming the flag
// and what is wrong with it, the same way in every tool.
#include "CommandLine.h"
#include "LightOverrides.h"
#include "Median.h"
#include "OptionValues.h"
#include "SettingOverrides.h"

#include "engine/util/Error.h"

#include "ErrorOf.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using tools::test::errorOf;

TEST(OptionValues, IntegersInRangeAreRead) {
    EXPECT_EQ(tools::parseInteger("--width", "1", 1, 16384), 1);
    EXPECT_EQ(tools::parseInteger("--width", "16384", 1, 16384), 16384);
    EXPECT_EQ(tools::parseInteger("--warmup", "0", 0, 1000), 0);
}

TEST(OptionValues, BadIntegerNamesTheFlagAndTheText) {
    for (const char* text : {"", "12px", "abc", " 12", "+12", "1.5", "99999999999999999999"})
        EXPECT_EQ(errorOf([&] { tools::parseInteger("--frames", text, 1, 100); }),
                  std::string("--frames: \"") + text + "\" is not an integer in [1, 100]");
}

TEST(OptionValues, IntegerOutOfRangeNamesTheRange) {
    EXPECT_EQ(errorOf([] { tools::parseInteger("--width", "0", 1, 16384); }),
              "--width: \"0\" is not an integer in [1, 16384]");
    EXPECT_EQ(errorOf([] { tools::parseInteger("--width", "16385", 1, 16384); }),
              "--width: \"16385\" is not an integer in [1, 16384]");
    EXPECT_EQ(errorOf([] { tools::parseInteger("--width", "-3", 1, 16384); }),
              "--width: \"-3\" is not an integer in [1, 16384]");
}

TEST(OptionValues, ListsKeepTheirOrder) {
    EXPECT_EQ(tools::parseList("--variants", "woo,standard"), (std::vector<std::string>{"woo", "standard"}));
    EXPECT_EQ(tools::parseList("--variants", "woo"), (std::vector<std::string>{"woo"}));
    EXPECT_EQ(tools::parseIntegerList("--resolutions", "512,2048", 1, 65536), (std::vector<int>{512, 2048}));
}

TEST(OptionValues, EmptyListItemIsAnErrorNamingTheFlag) {
    for (const char* text : {"", ",woo", "woo,", "woo,,standard"})
        EXPECT_EQ(errorOf([&] { tools::parseList("--variants", text); }),
                  std::string("--variants: empty item in \"") + text + "\" (items are separated by single commas)");
}

TEST(OptionValues, DuplicateListItemIsAnErrorNamingFlagAndItem) {
    EXPECT_EQ(errorOf([] { tools::parseList("--formats", "d24,d32f,d24"); }),
              "--formats: \"d24\" is listed twice in \"d24,d32f,d24\"");
    EXPECT_EQ(errorOf([] { tools::parseIntegerList("--resolutions", "512,512", 1, 65536); }),
              "--resolutions: \"512\" is listed twice in \"512,512\"");
}

TEST(OptionValues, UnknownNameListsTheKnownOnes) {
    EXPECT_EQ(errorOf([] { tools::parseNames("--variants", "woo,wang", {"standard", "woo", "backface"}); }),
              "--variants: unknown value \"wang\" (known: standard,woo,backface)");
    EXPECT_EQ(errorOf([] { tools::parseIntegerList("--resolutions", "512,big", 1, 65536); }),
              "--resolutions: \"big\" is not an integer in [1, 65536]");
}

TEST(OptionValues, AssignmentNeedsBothSides) {
    EXPECT_EQ(tools::parseAssignment("--light", "sun=woo"), (std::pair<std::string, std::string>{"sun", "woo"}));
    EXPECT_EQ(tools::parseAssignment("--light", "a=b=c").second, "b=c");
    for (const char* text : {"sun", "=woo", "sun="})
        EXPECT_EQ(errorOf([&] { tools::parseAssignment("--light", text); }),
                  std::string("--light: \"") + text + "\" must be NAME=VALUE");
}

TEST(OptionValues, KeyLightTypes) {
    EXPECT_EQ(tools::parseLightType("--key-light", "spot"), engine::Light::Type::Spot);
    EXPECT_EQ(tools::parseLightType("--key-light", "point"), engine::Light::Type::Point);
    EXPECT_EQ(tools::parseLightType("--key-light", "directional"), engine::Light::Type::Directional);
    EXPECT_EQ(errorOf([] { tools::parseLightType("--key-light", "sun"); }),
              "--key-light: \"sun\" is not spot, point or directional");
}

TEST(SettingOverrides, ValueIsJsonOrABareWord) {
    const tools::SettingOverride number = tools::parseSettingOverride("--set", "shadowmap_plugin.resolution=512");
    EXPECT_EQ(number.plugin, "shadowmap_plugin");
    EXPECT_EQ(number.key, "resolution");
    EXPECT_EQ(number.value, 512);
    EXPECT_EQ(tools::parseSettingOverride("--set", "shadowmap_plugin.variant=woo").value, "woo");
    EXPECT_EQ(tools::parseSettingOverride("--set", "p.offset=[1,2]").value, nlohmann::json::array({1, 2}));
}

TEST(SettingOverrides, SetWithoutEqualsIsAnError) {
    EXPECT_EQ(errorOf([] { tools::parseSettingOverride("--set", "shadowmap_plugin.resolution"); }),
              "--set: \"shadowmap_plugin.resolution\" must be PLUGIN.KEY=VALUE (no '=')");
}

TEST(SettingOverrides, TargetMustBePluginDotKey) {
    for (const char* target : {"resolution", ".resolution", "shadowmap_plugin."})
        EXPECT_EQ(errorOf([&] { tools::parseSettingOverride("--set", std::string(target) + "=1"); }),
                  std::string("--set: \"") + target + "=1\" must be PLUGIN.KEY=VALUE (\"" + target +
                      "\" is not PLUGIN.KEY)");
    EXPECT_EQ(errorOf([] { tools::parseSettingOverride("--set", "p.key="); }),
              "--set: \"p.key=\" must be PLUGIN.KEY=VALUE (no value)");
}

TEST(SettingOverrides, AppliedToTheNamedPluginOnly) {
    engine::EngineConfig config;
    config.sourcePath = "engine.json";
    config.plugins = {{"shadowmap_plugin", {{"resolution", 2048}}}, {"other", {}}};
    tools::applySettingOverrides(config, {tools::parseSettingOverride("--set", "shadowmap_plugin.resolution=512")});
    EXPECT_EQ(config.plugins[0].settings["resolution"], 512);
    EXPECT_FALSE(config.plugins[1].settings.contains("resolution"));
    try {
        tools::applySettingOverrides(config, {tools::parseSettingOverride("--set", "nope.key=1")});
        ADD_FAILURE() << "an override of a plugin the config does not load was accepted";
    } catch (const engine::InputError& error) {
        EXPECT_STREQ(error.what(),
                     "--set nope.key=1: the config engine.json loads no plugin \"nope\" (it loads: shadowmap_plugin, other)");
    }
}

// Which value of two was meant is not the tool's to guess: the second is refused, naming both.
TEST(SettingOverrides, TheSameKeyTwiceIsAnErrorNamingBothValues) {
    std::vector<tools::SettingOverride> overrides;
    tools::addSettingOverride(overrides, "--set", "shadowmap_plugin.resolution=512");
    tools::addSettingOverride(overrides, "--set", "shadowmap_plugin.cache_maps=false");
    ASSERT_EQ(overrides.size(), 2u);
    EXPECT_EQ(errorOf([&] { tools::addSettingOverride(overrides, "--set", "shadowmap_plugin.resolution=1024"); }),
              "--set shadowmap_plugin.resolution is given twice: 512 and 1024");
}

TEST(LightOverrides, LightSetSplitsAtTheLastDotBeforeTheValue) {
    const tools::LightOverride option = tools::parseLightSetting("--light-set", "Light.001.polygon_offset=[1,2]");
    EXPECT_EQ(option.light, "Light.001");  // Blender's names hold dots; keys never do
    EXPECT_EQ(option.key, "polygon_offset");
    EXPECT_EQ(option.value, nlohmann::json::array({1, 2}));
    EXPECT_EQ(option.text, "--light-set Light.001.polygon_offset=[1,2]");
    EXPECT_EQ(tools::parseLightSetting("--light-set", "sun.filter=nearest").value, "nearest");
    EXPECT_EQ(errorOf([] { tools::parseLightSetting("--light-set", "sun=512"); }),
              "--light-set: \"sun=512\" must be NAME.KEY=VALUE (\"sun\" is not NAME.KEY)");
    EXPECT_EQ(errorOf([] { tools::parseLightSetting("--light-set", "sun.resolution="); }),
              "--light-set: \"sun.resolution=\" must be NAME.KEY=VALUE (no value)");
}

TEST(LightOverrides, LightIsShortForTheVariantKey) {
    const tools::LightOverride option = tools::parseLightVariant("--light", "sun=none");
    EXPECT_EQ(option.light, "sun");
    EXPECT_EQ(option.key, "variant");
    EXPECT_EQ(option.value, "none");  // a word, not JSON's null
    EXPECT_EQ(errorOf([] { tools::parseLightVariant("--light", "sun"); }), "--light: \"sun\" must be NAME=VARIANT");
}

// intensity and color are the light's own: their values are checked as they are parsed,
// each refusal naming the option, the light, the key and the value.
TEST(LightOverrides, LightPropertiesAreCheckedAsTheyAreParsed) {
    EXPECT_EQ(tools::parseLightSetting("--light-set", "Light.001.intensity=54351").value, 54351);
    EXPECT_EQ(tools::parseLightSetting("--light-set", "sun.intensity=0").value, 0);  // emits nothing: allowed
    EXPECT_EQ(tools::parseLightSetting("--light-set", "sun.color=[1,0.5,0]").value, nlohmann::json({1, 0.5, 0}));
    EXPECT_EQ(errorOf([] { tools::parseLightSetting("--light-set", "sun.intensity=-1"); }),
              "--light-set sun.intensity=-1: light \"sun\".intensity must be a finite number >= 0 (0: the light "
              "emits nothing), got -1");
    for (const char* bad : {"nan", "inf", "bright", "[2]", "1e39", "true"})
        EXPECT_NE(errorOf([&] { tools::parseLightSetting("--light-set", std::string("sun.intensity=") + bad); })
                      .find("light \"sun\".intensity must be a finite number >= 0"),
                  std::string::npos)
            << bad;
    for (const char* bad : {"[1,2]", "[1,2,-3]", "[1,2,3,4]", "red", "1", "[1,\"a\",3]"})
        EXPECT_NE(errorOf([&] { tools::parseLightSetting("--light-set", std::string("lamp.color=") + bad); })
                      .find("light \"lamp\".color must be [r, g, b], three finite numbers >= 0 (linear), got "),
                  std::string::npos)
            << bad;
    EXPECT_TRUE(tools::isLightPropertyKey("intensity"));
    EXPECT_TRUE(tools::isLightPropertyKey("color"));
    EXPECT_FALSE(tools::isLightPropertyKey("resolution"));
}

// A light property lands on the scene's light, every other key is passed on for the plugins,
// and a glTF light that another node places too is said to change there as well.
TEST(LightOverrides, LightPropertiesSetTheScenesLightAndTheRestGoToThePlugins) {
    engine::Scene scene;
    scene.lights.resize(2);
    scene.lights[0].name = "sun";
    scene.lights[0].intensity = 3.0f;
    scene.lights[1].intensity = 7.0f;  // unnamed: its instances take their nodes' names
    scene.nodes.resize(3);
    scene.nodes[1].name = "lamp_a";
    scene.nodes[2].name = "lamp_b";
    scene.lightInstances = {{0, 0}, {1, 1}, {2, 1}};
    const std::vector<tools::LightOverride> options = {
        tools::parseLightSetting("--light-set", "sun.intensity=5"),
        tools::parseLightSetting("--light-set", "sun.resolution=512"),
        tools::parseLightSetting("--light-set", "sun.color=[1,0.5,0.25]")};
    std::vector<std::string> warnings;
    const std::vector<tools::LightOverride> rest = tools::applyLightProperties(scene, options, warnings);
    ASSERT_EQ(rest.size(), 1u);
    EXPECT_EQ(rest[0].key, "resolution");
    EXPECT_EQ(scene.lights[0].intensity, 5.0f);
    EXPECT_EQ(scene.lights[0].color, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(scene.lights[1].intensity, 7.0f);
    EXPECT_TRUE(warnings.empty());

    tools::applyLightProperties(scene, {tools::parseLightSetting("--light-set", "lamp_a.intensity=0")}, warnings);
    EXPECT_EQ(scene.lights[1].intensity, 0.0f);
    EXPECT_FALSE(scene.lights[1].emitsLight());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "--light-set lamp_a.intensity=0 also sets light \"lamp_b\": it places the same glTF light "
                           "(intensity is the light's, shared by every node that places it)");
}

// "2" and "sun" are the same light once resolved: the repeat is found however it was typed.
TEST(LightOverrides, TheSameLightAndKeyTwiceIsAnErrorNamingBoth) {
    const std::map<std::string, std::string> names = {{"sun", "sun"}, {"2", "sun"}, {"spot", "spot"}};
    const auto resolve = [&](const std::string& typed) { return names.at(typed); };
    const std::vector<tools::LightOverride> distinct = {tools::parseLightVariant("--light", "sun=woo"),
                                                        tools::parseLightSetting("--light-set", "2.resolution=512"),
                                                        tools::parseLightVariant("--light", "spot=woo")};
    EXPECT_EQ(tools::resolveLightOverrides(distinct, resolve)[1].light, "sun");
    try {
        tools::resolveLightOverrides({tools::parseLightVariant("--light", "sun=woo"),
                                      tools::parseLightSetting("--light-set", "2.variant=backface")},
                                     resolve);
        ADD_FAILURE() << "a light's variant given twice was accepted";
    } catch (const engine::InputError& error) {
        EXPECT_STREQ(error.what(), "--light-set 2.variant=backface: light \"sun\".variant is already set by "
                                   "--light sun=woo (\"woo\" and \"backface\"): give each light and key once");
    }
}

TEST(Median, OddEvenAndEmpty) {
    EXPECT_EQ(tools::median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(tools::median({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(tools::median({5.0}), 5.0);
    EXPECT_EQ(tools::median({}), 0.0);
}

TEST(Median, PercentileIsTheNearestRankSoItIsAValueThatHappened) {
    std::vector<double> frames;
    for (int i = 1; i <= 200; ++i) frames.push_back(static_cast<double>(i));
    // 200 values: the 99th percentile is the 198th smallest, the maximum the 200th.
    EXPECT_EQ(tools::percentile(frames, 0.99), 198.0);
    EXPECT_EQ(tools::percentile(frames, 1.0), 200.0);
    // Under 100 values the p99 is the maximum: one hitch in 60 frames shows.
    const tools::TimeSummary hitch = tools::summarizeTimes({10.0, 11.0, 10.5, 400.0, 10.2});
    EXPECT_EQ(hitch.median, 10.5);
    EXPECT_EQ(hitch.p99, 400.0);
    EXPECT_EQ(hitch.max, 400.0);
    EXPECT_EQ(tools::percentile({}, 0.99), 0.0);
}

// The flag loop: values are taken whatever they look like, switches take none, and the
// errors it owns name the flag.
TEST(CommandLine, FlagLoopErrors) {
    std::vector<std::string> words = {"tool", "--width", "64", "--truth", "--typo", "1"};
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    std::vector<std::string> seen;
    const auto handler = [&](const std::string& flag, const std::string& value) {
        seen.push_back(flag + "=" + value);
        return flag != "--typo";
    };
    EXPECT_EQ(errorOf([&] { tools::parseFlags(int(argv.size()), argv.data(), {"--truth"}, handler); }),
              "unknown option --typo");
    EXPECT_EQ(seen, (std::vector<std::string>{"--width=64", "--truth=", "--typo=1"}));
    EXPECT_EQ(errorOf([&] { tools::parseFlags(2, argv.data(), {"--truth"}, handler); }), "--width: missing value");
    // A typo as the last argument is as unknown as one mid-line (it once read "--typo:
    // missing value"), and a known flag whose value check throws on "" still lacks its value.
    EXPECT_EQ(errorOf([&] { tools::parseFlags(5, argv.data(), {"--truth"}, handler); }), "unknown option --typo");
    const auto throwingOnEmpty = [](const std::string& flag, const std::string& value) {
        if (value.empty()) throw std::invalid_argument(flag + ": not a number");
        return true;
    };
    EXPECT_EQ(errorOf([&] { tools::parseFlags(2, argv.data(), {}, throwingOnEmpty); }), "--width: missing value");
}

} // namespace
