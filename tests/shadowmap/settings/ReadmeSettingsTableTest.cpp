// The README's per-light settings table is the allowed-values table (settingKeys()) written
// out: this test renders it and compares it with the lines between the README's markers,
// so the two cannot drift. On a difference it prints the table to paste.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/FormatNumber.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

constexpr const char* kBegin = "<!-- shadow settings table: generated from shadowmap::settingKeys(), checked by "
                               "ReadmeSettingsTable -->";
constexpr const char* kEnd = "<!-- end of shadow settings table -->";

std::string defaultCell(const shadowmap::SettingKey& key) {
    const nlohmann::json& value = key.defaultValue;
    if (value.is_null()) return key.defaultNote;
    if (value.is_string()) return "`" + value.get<std::string>() + "`";
    if (value.is_boolean()) return value.get<bool>() ? "`true`" : "`false`";
    if (value.is_array()) return "[" + engine::formatNumber(value[0].get<double>()) + ", " +
                                 engine::formatNumber(value[1].get<double>()) + "]";
    return engine::formatNumber(value.get<double>());
}

std::string markdownTable() {
    std::string table = "| key | values | default | meaning |\n|---|---|---|---|\n";
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys())
        table += "| `" + key.name + "` | " + key.values + " | " + defaultCell(key) + " | " + key.description + " |\n";
    return table;
}

std::string readFile(const char* path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

} // namespace

TEST(ReadmeSettingsTable, IsTheAllowedValuesTable) {
    const std::string readme = readFile(README_PATH);
    ASSERT_FALSE(readme.empty()) << "cannot read " << README_PATH;
    const std::size_t begin = readme.find(kBegin);
    ASSERT_NE(begin, std::string::npos) << README_PATH << " has no line " << kBegin;
    const std::size_t tableStart = readme.find('\n', begin) + 1;
    const std::size_t end = readme.find(kEnd, tableStart);
    ASSERT_NE(end, std::string::npos) << README_PATH << " has no line " << kEnd;
    const std::string expected = markdownTable();
    EXPECT_EQ(readme.substr(tableStart, end - tableStart), expected)
        << "The README's settings table differs from shadowmap::settingKeys(); the table as the API "
           "has it:\n" << kBegin << "\n" << expected << kEnd;
}

TEST(ReadmeSettingsTable, TheExampleAboveItParsesToTheDefaults) {
    const std::string readme = readFile(README_PATH);
    const std::string start = "\"extras\": {\"shadow\":";
    const std::size_t begin = readme.find(start);
    ASSERT_NE(begin, std::string::npos) << README_PATH << " has no example starting " << start;
    const std::size_t end = readme.find("\n```", begin);
    ASSERT_NE(end, std::string::npos);
    const nlohmann::json example = nlohmann::json::parse("{" + readme.substr(begin, end - begin) + "}");
    shadowmap::ShadowSettings settings;
    ASSERT_NO_THROW(settings = shadowmap::parseSettings(example["extras"]["shadow"], "README.md", "example"));
    // It spells out the default offset; without it, it is the built-in defaults exactly.
    EXPECT_EQ(settings.effectivePolygonOffset(), shadowmap::ShadowSettings{}.effectivePolygonOffset());
    settings.polygonOffset.reset();
    EXPECT_EQ(settings, shadowmap::ShadowSettings{}) << example.dump();
}
