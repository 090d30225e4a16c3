// printSettings -> parseSettings gives back the very settings, key by key and all together,
// and the defaults print as documented (README, DESIGN.md).
#include "shadowmap/ShadowSettings.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace {

using shadowmap::ShadowSettings;

ShadowSettings roundTrip(const ShadowSettings& settings) {
    return shadowmap::parseSettings(shadowmap::printSettings(settings), "printed", "settings");
}

// One non-default value per key. Floats are ones binary cannot hold exactly (0.73, 4.3),
// so a print that widened float to double, or a parse that kept double, would show.
struct KeyChange {
    std::string key;
    std::function<void(ShadowSettings&)> change;
};

std::vector<KeyChange> oneChangePerKey() {
    return {
        {"variant", [](ShadowSettings& s) { s.variant = shadowmap::Variant::Woo; }},
        {"resolution", [](ShadowSettings& s) { s.resolution = 777; }},
        {"depth_format", [](ShadowSettings& s) { s.depthFormat = shadowmap::DepthFormat::D32F; }},
        {"filter", [](ShadowSettings& s) { s.filter = shadowmap::Filter::Nearest; }},
        {"filter_taps", [](ShadowSettings& s) { s.filterTaps = 40; }},
        {"filter_radius", [](ShadowSettings& s) { s.filterRadius = 2.73; }},
        {"normal_offset", [](ShadowSettings& s) { s.normalOffset = 1.37; }},
        {"bleed_reduction", [](ShadowSettings& s) { s.bleedReduction = 0.37; }},
        {"evsm_exponents", [](ShadowSettings& s) { s.evsmExponents = glm::vec2(33.3f, 4.3f); }},
        {"moments_mipmaps", [](ShadowSettings& s) { s.momentsMipmaps = true; }},
        {"polygon_offset", [](ShadowSettings& s) { s.polygonOffset = glm::vec2(1.1f, 4.3f); }},
        {"dimming", [](ShadowSettings& s) { s.dimming = 0.73f; }},
        {"near_plane", [](ShadowSettings& s) { s.nearPlane = 0.1; }},
        {"far_plane", [](ShadowSettings& s) { s.farPlane = 123.456; }},
        {"reversed_z", [](ShadowSettings& s) { s.reversedZ = true; }},
        {"polygon_offset_clamp", [](ShadowSettings& s) { s.polygonOffsetClamp = 2.7f; }},
        {"cascades", [](ShadowSettings& s) { s.cascades = 3; }},
        {"cascade_lambda", [](ShadowSettings& s) { s.cascadeLambda = 0.3; }},
        {"cascade_blend", [](ShadowSettings& s) { s.cascadeBlend = 0.25; }},
        {"stable", [](ShadowSettings& s) { s.stable = false; }},
        {"shadow_distance", [](ShadowSettings& s) { s.shadowDistance = 42.3; }},
        {"shadow_fade", [](ShadowSettings& s) { s.shadowFade = 0.27; }},
        {"light_radius", [](ShadowSettings& s) { s.lightRadius = 0.35; }},
        {"angular_diameter", [](ShadowSettings& s) { s.angularDiameter = 0.0093; }},
        {"cull_unseen_casters", [](ShadowSettings& s) { s.cullUnseenCasters = false; }},
        {"projection", [](ShadowSettings& s) { s.projection = shadowmap::Projection::Lispsm; }},
        {"lispsm_n_scale", [](ShadowSettings& s) { s.lispsmNScale = 2.5; }},
        {"caster_lod", [](ShadowSettings& s) { s.casterLod = 0.5; }},
    };
}

} // namespace

TEST(ShadowSettingsRoundTrip, EveryKeyHasAChangeBelow) {
    std::set<std::string> covered;
    for (const KeyChange& change : oneChangePerKey()) covered.insert(change.key);
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys())
        EXPECT_TRUE(covered.count(key.name)) << key.name << " has no round-trip case";
    EXPECT_EQ(covered.size(), shadowmap::settingKeys().size());
}

TEST(ShadowSettingsRoundTrip, DefaultsPrintAsDocumented) {
    // README's table and DESIGN.md: standard, 2048, d24, pcf, dimming 0.4; no forced
    // planes, no explicit offset, no reversal, no clamp, no shadow distance, a light without
    // a size, casters whose shadow nobody sees left out.
    const nlohmann::json expected = {{"variant", "standard"}, {"resolution", 2048}, {"depth_format", "d24"},
                                     {"filter", "pcf"},       {"filter_taps", 16},      {"filter_radius", 0.0},   {"normal_offset", 0.25},
                                     {"bleed_reduction", 0.3},     {"evsm_exponents", {40.0, 5.0}},
                                     {"moments_mipmaps", false},    {"dimming", 0.4},     {"reversed_z", false},
                                     {"polygon_offset_clamp", 0.0}, {"cascades", "auto"},
                                     {"cascade_lambda", 0.75},     {"cascade_blend", 0.0},
                                     {"stable", true},             {"shadow_distance", 0.0},
                                     {"shadow_fade", 0.1},         {"light_radius", 0.0},
                                     {"angular_diameter", 0.0},    {"cull_unseen_casters", true},
                                     {"projection", "uniform"},    {"lispsm_n_scale", 1.0},
                                     {"caster_lod", 0.0}};
    EXPECT_EQ(shadowmap::printSettings(ShadowSettings{}), expected);
    EXPECT_EQ(roundTrip(ShadowSettings{}), ShadowSettings{});
    // The float 0.4 prints as the decimal it was written as, not 0.4000000059604645.
    EXPECT_EQ(shadowmap::printSettings(ShadowSettings{})["dimming"].dump(), "0.4");
}

TEST(ShadowSettingsRoundTrip, EachKeyAloneSurvivesPrintAndParse) {
    const nlohmann::json defaults = shadowmap::printSettings(ShadowSettings{});
    for (const KeyChange& change : oneChangePerKey()) {
        ShadowSettings settings;
        change.change(settings);
        ASSERT_NE(settings, ShadowSettings{}) << change.key << ": the change changes nothing";
        const nlohmann::json printed = shadowmap::printSettings(settings);
        ASSERT_TRUE(printed.contains(change.key)) << printed.dump();
        EXPECT_NE(printed[change.key], defaults.value(change.key, nlohmann::json())) << change.key;
        EXPECT_EQ(roundTrip(settings), settings) << change.key << ": " << printed.dump();
    }
}

TEST(ShadowSettingsRoundTrip, AllKeysTogetherSurvivePrintAndParse) {
    ShadowSettings settings;
    for (const KeyChange& change : oneChangePerKey()) change.change(settings);
    // Together they are valid too (reversed_z with d32f, near below far).
    EXPECT_NO_THROW(shadowmap::checkLimits(settings, 4096, "printed", "settings"));
    EXPECT_EQ(roundTrip(settings), settings) << shadowmap::printSettings(settings).dump();
}

TEST(ShadowSettingsRoundTrip, AnInfiniteFarPlanePrintsAsTheWordInfinite) {
    ShadowSettings settings;
    settings.depthFormat = shadowmap::DepthFormat::D32F;
    settings.reversedZ = true;
    settings.farPlane = std::numeric_limits<double>::infinity();
    const nlohmann::json printed = shadowmap::printSettings(settings);
    EXPECT_EQ(printed["far_plane"], "infinite");
    EXPECT_EQ(roundTrip(settings), settings);
}

TEST(ShadowSettingsRoundTrip, EveryVariantFormatAndFilterSurvives) {
    for (const std::string& variant : shadowmap::settingKey("variant").choices)
        for (const std::string& format : shadowmap::settingKey("depth_format").choices)
            for (const std::string& filter : shadowmap::settingKey("filter").choices) {
                const nlohmann::json json = {{"variant", variant}, {"depth_format", format}, {"filter", filter}};
                const ShadowSettings settings = shadowmap::parseSettings(json, "test", "settings");
                EXPECT_EQ(shadowmap::toString(settings.variant), variant);
                EXPECT_EQ(shadowmap::toString(settings.depthFormat), format);
                EXPECT_EQ(shadowmap::toString(settings.filter), filter);
                EXPECT_EQ(roundTrip(settings), settings) << json.dump();
            }
}

TEST(ShadowSettingsDefaults, PolygonOffsetFollowsVariantFilterAndDepthDirection) {
    using shadowmap::Filter;
    using shadowmap::Variant;
    // The measured defaults of the header's table: units 8 (128 reversed), factor 1 for one
    // tap and 2 for PCF; woo, backface and none draw without an offset.
    EXPECT_EQ(shadowmap::defaultPolygonOffset(Variant::Standard, Filter::Nearest, false), glm::vec2(1.0f, 8.0f));
    EXPECT_EQ(shadowmap::defaultPolygonOffset(Variant::Standard, Filter::Pcf, false), glm::vec2(2.0f, 8.0f));
    // pcss's taps are 2x2 bilinear comparisons: pcf's offset.
    EXPECT_EQ(shadowmap::defaultPolygonOffset(Variant::Standard, Filter::Pcss, false), glm::vec2(2.0f, 8.0f));
    EXPECT_EQ(shadowmap::defaultPolygonOffset(Variant::Standard, Filter::Pcf, true), glm::vec2(2.0f, 128.0f));
    for (Variant variant : {Variant::Woo, Variant::Backface, Variant::None})
        EXPECT_EQ(shadowmap::defaultPolygonOffset(variant, Filter::Pcf, false), glm::vec2(0.0f));

    ShadowSettings backface;
    backface.variant = Variant::Backface;
    EXPECT_EQ(backface.effectivePolygonOffset(), glm::vec2(0.0f));
    // Open casters under backface are drawn two-sided with the standard offset.
    EXPECT_EQ(backface.standardPolygonOffset(), glm::vec2(2.0f, 8.0f));
    backface.polygonOffset = glm::vec2(3.0f, 5.0f);  // explicit: used as is by every variant
    EXPECT_EQ(backface.effectivePolygonOffset(), glm::vec2(3.0f, 5.0f));
    EXPECT_EQ(backface.standardPolygonOffset(), glm::vec2(3.0f, 5.0f));
}
