// The allowed-values table agrees with what applySettings accepts and with the defaults:
// tools build their menus and checks from it, so a value it lists must parse and its
// default must be the default.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

shadowmap::ShadowSettings applied(const std::string& key, const nlohmann::json& value) {
    return shadowmap::parseSettings({{key, value}}, "table", "settings");
}

} // namespace

TEST(SettingKeys, EveryChoiceParsesAndPrintsBackTheSame) {
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) {
        if (key.kind != shadowmap::SettingKind::Choice) continue;
        ASSERT_FALSE(key.choices.empty()) << key.name;
        for (const std::string& choice : key.choices)
            EXPECT_EQ(shadowmap::printSettings(applied(key.name, choice))[key.name], choice) << key.name;
    }
    // The enums' every value, in declaration order (the order tools cycle through).
    EXPECT_EQ(shadowmap::settingKey("variant").choices,
              (std::vector<std::string>{"standard", "woo", "backface", "none", "volume"}));
    EXPECT_EQ(shadowmap::settingKey("depth_format").choices, (std::vector<std::string>{"d16", "d24", "d32f"}));
    EXPECT_EQ(shadowmap::settingKey("filter").choices, (std::vector<std::string>{"nearest", "pcf", "pcss", "vsm", "evsm"}));
}

TEST(SettingKeys, DefaultsAreTheDefaults) {
    const shadowmap::ShadowSettings defaults;
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) {
        if (key.defaultValue.is_null()) {
            EXPECT_FALSE(key.defaultNote.empty()) << key.name << ": a key without a default value says why";
            EXPECT_FALSE(shadowmap::printSettings(defaults).contains(key.name)) << key.name;
            continue;
        }
        EXPECT_EQ(applied(key.name, key.defaultValue), defaults) << key.name;
        if (key.kind == shadowmap::SettingKind::Choice) {
            EXPECT_NE(std::find(key.choices.begin(), key.choices.end(), key.defaultValue.get<std::string>()),
                      key.choices.end())
                << key.name;
        }
    }
    EXPECT_EQ(shadowmap::settingKey("polygon_offset").defaultNote,
              "standard: [1, 8] nearest, [2, 8] pcf and pcss, units 128 with reversed_z; woo, backface: none");
}

TEST(SettingKeys, BoundsAndStepsAreWhatParsingAccepts) {
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) {
        EXPECT_FALSE(key.values.empty()) << key.name;
        EXPECT_FALSE(key.description.empty()) << key.name;
        EXPECT_EQ(key.description.find('|'), std::string::npos) << key.name << ": would split a Markdown table cell";
        if (key.minimum) {
            EXPECT_NO_THROW(applied(key.name, *key.minimum)) << key.name;
        }
        if (key.maximum) {
            EXPECT_NO_THROW(applied(key.name, *key.maximum)) << key.name;
        }
        // Just outside a bound is refused: the bounds are the real ones, not a guess. The
        // step 1 is the resolution's granularity; dimming and the clamp are continuous.
        if (key.minimum) {
            EXPECT_THROW(applied(key.name, *key.minimum - 1.0), engine::InputError) << key.name;
        }
        if (key.maximum) {
            EXPECT_THROW(applied(key.name, *key.maximum + 1.0), engine::InputError) << key.name;
        }
        for (double step : key.steps) {
            EXPECT_GE(step, key.minimum.value_or(step)) << key.name;
            EXPECT_LE(step, key.maximum.value_or(step)) << key.name;
            EXPECT_NO_THROW(applied(key.name, step)) << key.name;
        }
    }
    EXPECT_EQ(shadowmap::settingKey("resolution").steps, (std::vector<double>{512, 1024, 2048, 4096}));
    EXPECT_THROW(shadowmap::settingKey("colour"), std::logic_error);
}

TEST(SettingKeys, WordsAcceptedForNumbersParse) {
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) {
        if (key.kind != shadowmap::SettingKind::Number) continue;
        for (const std::string& word : key.choices) {
            EXPECT_NO_THROW(applied(key.name, word)) << key.name;
        }
    }
    EXPECT_EQ(shadowmap::settingKey("far_plane").choices, std::vector<std::string>{"infinite"});
}
