// Every bad value is an InputError whose one line names the source file, the light, the key
// and the reason, e.g. scene.gltf: light "sun": extras.shadow.dimming: must be in [0, 1], got 1.5
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

constexpr const char* kSource = "scene.gltf";
constexpr const char* kObject = "light \"sun\": extras.shadow";

struct BadValue {
    const char* what;      // for failure messages
    nlohmann::json json;   // the light's extras.shadow
    std::string key;       // the key path the message must name
    std::string reason;    // the reason it must give
};

// The message of the InputError that applySettings (and then checkLimits, with a GL limit
// of 4096 texels) throws for `json`; "no error" when neither throws.
std::string errorOf(const nlohmann::json& json) {
    try {
        const shadowmap::ShadowSettings settings = shadowmap::parseSettings(json, kSource, kObject);
        shadowmap::checkLimits(settings, 4096, kSource, kObject);
    } catch (const engine::InputError& error) {
        return error.what();
    }
    return "no error";
}

void expectNamed(const BadValue& bad) {
    const std::string message = errorOf(bad.json);
    SCOPED_TRACE(std::string(bad.what) + ": " + bad.json.dump() + " -> " + message);
    EXPECT_EQ(message.rfind(kSource, 0), 0u) << "the source comes first";
    EXPECT_NE(message.find("light \"sun\""), std::string::npos);
    EXPECT_NE(message.find(std::string(kObject) + "." + bad.key + ": "), std::string::npos) << bad.key;
    EXPECT_NE(message.find(bad.reason), std::string::npos) << bad.reason;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInfinity = std::numeric_limits<double>::infinity();

} // namespace

TEST(ShadowSettingsErrors, UnknownKeyListsTheKnownOnes) {
    std::string known;
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys()) known += (known.empty() ? "" : ", ") + key.name;
    EXPECT_EQ(known, "variant, resolution, depth_format, filter, filter_taps, filter_radius, bleed_reduction, evsm_exponents, "
                     "moments_mipmaps, normal_offset, polygon_offset, dimming, near_plane, far_plane, "
                     "reversed_z, polygon_offset_clamp, cascades, cascade_lambda, cascade_blend, stable, shadow_distance, shadow_fade, "
                     "light_radius, angular_diameter, cull_unseen_casters, projection, lispsm_n_scale, caster_lod");
    expectNamed({"unknown key", {{"colour", "red"}}, "colour", "unknown key (known: " + known + ")"});
}

TEST(ShadowSettingsErrors, CascadeSettingsOutOfRangeAreNamed) {
    expectNamed({"cascades 0", {{"cascades", 0}}, "cascades", "must be \"auto\" or a whole number in [1, 4], got 0"});
    expectNamed({"cascades 5", {{"cascades", 5}}, "cascades", "must be \"auto\" or a whole number in [1, 4], got 5"});
    expectNamed({"cascades 2.5", {{"cascades", 2.5}}, "cascades", "must be \"auto\" or a whole number in [1, 4], got 2.5"});
    expectNamed({"cascades many", {{"cascades", "many"}}, "cascades",
                 "must be \"auto\" or a whole number in [1, 4], got \"many\""});
    expectNamed({"lambda 1.5", {{"cascade_lambda", 1.5}}, "cascade_lambda", "must be in [0, 1], got 1.5"});
    expectNamed({"blend 0.6", {{"cascade_blend", 0.6}}, "cascade_blend", "must be in [0, 0.5], got 0.6"});
    expectNamed({"blend -0.1", {{"cascade_blend", -0.1}}, "cascade_blend", "must be in [0, 0.5], got -0.1"});
    expectNamed({"stable type", {{"stable", "yes"}}, "stable", "must be true or false"});
}

TEST(ShadowSettingsErrors, ShadowDistanceAndFadeOutOfRangeAreNamed) {
    expectNamed({"distance -1", {{"shadow_distance", -1}}, "shadow_distance",
                 "must be a finite number >= 0 (0: no limit), got -1"});
    expectNamed({"distance text", {{"shadow_distance", "far"}}, "shadow_distance", "must be a number"});
    expectNamed({"fade 1.5", {{"shadow_fade", 1.5}}, "shadow_fade", "must be in [0, 1], got 1.5"});
    expectNamed({"fade -0.1", {{"shadow_fade", -0.1}}, "shadow_fade", "must be in [0, 1], got -0.1"});
}

TEST(ShadowSettingsErrors, BadChoicesNameTheKnownValues) {
    expectNamed({"variant", {{"variant", "soft"}}, "variant",
                 "unknown variant \"soft\" (known: standard, woo, backface, none, volume)"});
    expectNamed({"variant type", {{"variant", 3}}, "variant", "must be a string"});
    expectNamed({"depth format", {{"depth_format", "d32"}}, "depth_format",
                 "unknown depth format \"d32\" (known: d16, d24, d32f)"});
    expectNamed({"filter", {{"filter", "linear"}}, "filter", "unknown filter \"linear\" (known: nearest, pcf, pcss, vsm, evsm)"});
    expectNamed({"reversed_z type", {{"reversed_z", "yes"}}, "reversed_z", "must be true or false"});
}

TEST(ShadowSettingsErrors, BadNumbersSayWhatIsAccepted) {
    expectNamed({"resolution 0", {{"resolution", 0}}, "resolution", "must be a whole number of texels >= 1, got 0"});
    expectNamed({"resolution 1.5", {{"resolution", 1.5}}, "resolution",
                 "must be a whole number of texels >= 1, got 1.5"});
    expectNamed({"resolution 2^21", {{"resolution", 1 << 21}}, "resolution",
                 "2097152 texels is beyond any GL_MAX_TEXTURE_SIZE"});
    expectNamed({"resolution NaN", {{"resolution", kNaN}}, "resolution", "must be finite"});
    expectNamed({"resolution text", {{"resolution", "big"}}, "resolution", "must be a number"});
    expectNamed({"dimming 1.5", {{"dimming", 1.5}}, "dimming", "must be in [0, 1], got 1.5"});
    expectNamed({"dimming -0.1", {{"dimming", -0.1}}, "dimming", "must be in [0, 1], got -0.1"});
    expectNamed({"dimming NaN", {{"dimming", kNaN}}, "dimming", "must be finite"});
    expectNamed({"near_plane 0", {{"near_plane", 0}}, "near_plane", "must be a distance > 0, got 0"});
    expectNamed({"near_plane infinite", {{"near_plane", kInfinity}}, "near_plane", "must be finite"});
    expectNamed({"far_plane word", {{"far_plane", "far"}}, "far_plane",
                 "must be a distance > 0 or \"infinite\", got \"far\""});
    expectNamed({"far_plane -2", {{"far_plane", -2}}, "far_plane", "must be a distance > 0 or \"infinite\", got -2"});
    expectNamed({"clamp -1", {{"polygon_offset_clamp", -1}}, "polygon_offset_clamp",
                 "must be a slope >= 0 (0: unclamped), got -1"});
}

TEST(ShadowSettingsErrors, ALightsSizeIsAFiniteNumberNotBelowZero) {
    expectNamed({"radius -1", {{"light_radius", -1}}, "light_radius", "must be >= 0 world units (0: no size), got -1"});
    expectNamed({"radius NaN", {{"light_radius", kNaN}}, "light_radius", "must be finite"});
    expectNamed({"radius text", {{"light_radius", "big"}}, "light_radius", "must be a number"});
    expectNamed({"angle -0.01", {{"angular_diameter", -0.01}}, "angular_diameter",
                 "must be >= 0 radians (0: no size), got -0.01"});
    expectNamed({"angle infinite", {{"angular_diameter", kInfinity}}, "angular_diameter", "must be finite"});
    EXPECT_EQ(errorOf({{"light_radius", 0}, {"angular_diameter", 0.0093}}), "no error");
}

// The size key of the other type of light, set on the light itself: an error naming the key,
// whichever type; the type's own key passes.
TEST(ShadowSettingsErrors, ASizeOnTheWrongTypeOfLightIsNamed) {
    using Type = engine::Light::Type;
    auto messageFor = [](const nlohmann::json& json, Type type) -> std::string {
        try {
            shadowmap::checkSizeKeyForType(json, type, kSource, kObject);
        } catch (const engine::InputError& error) {
            return error.what();
        }
        return "no error";
    };
    EXPECT_EQ(messageFor({{"light_radius", 0.5}}, Type::Directional),
              std::string(kSource) + ": " + kObject +
                  ".light_radius: a directional light has no radius: size it with angular_diameter");
    for (Type type : {Type::Spot, Type::Point})
        EXPECT_EQ(messageFor({{"angular_diameter", 0.01}}, type),
                  std::string(kSource) + ": " + kObject +
                      ".angular_diameter: a spot or point light has no angular diameter: size it with light_radius");
    EXPECT_EQ(messageFor({{"angular_diameter", 0.01}}, Type::Directional), "no error");
    EXPECT_EQ(messageFor({{"light_radius", 0.5}}, Type::Spot), "no error");
    EXPECT_EQ(messageFor({{"light_radius", 0.5}}, Type::Point), "no error");
}

TEST(ShadowSettingsErrors, FilterTapsAreAWholeNumberInRange) {
    const std::string expected = "must be a whole number in [4, 64], got ";
    expectNamed({"taps 3", {{"filter_taps", 3}}, "filter_taps", expected + "3"});
    expectNamed({"taps 65", {{"filter_taps", 65}}, "filter_taps", expected + "65"});
    expectNamed({"taps 8.5", {{"filter_taps", 8.5}}, "filter_taps", expected + "8.5"});
    expectNamed({"taps NaN", {{"filter_taps", kNaN}}, "filter_taps", "must be finite"});
}

TEST(ShadowSettingsErrors, NormalOffsetIsInRange) {
    const std::string expected = "must be in [0, 8] texels, got ";
    expectNamed({"offset -0.5", {{"normal_offset", -0.5}}, "normal_offset", expected + "-0.5"});
    expectNamed({"offset 9", {{"normal_offset", 9}}, "normal_offset", expected + "9"});
    expectNamed({"offset text", {{"normal_offset", "1"}}, "normal_offset", "must be a number"});
}

TEST(ShadowSettingsErrors, FilterRadiusIsInRange) {
    const std::string expected = "must be in [0, 16] texels, got ";
    expectNamed({"radius -1", {{"filter_radius", -1}}, "filter_radius", expected + "-1"});
    expectNamed({"radius 16.5", {{"filter_radius", 16.5}}, "filter_radius", expected + "16.5"});
    expectNamed({"radius NaN", {{"filter_radius", kNaN}}, "filter_radius", "must be finite"});
}

// pcss without a size would silently be a hard shadow: an error naming the key to set, for
// the light's own type; a light without a shadow needs no size.
namespace {
// checkFilterForType's message for these settings on a light of this type; "no error" if none.
std::string filterErrorFor(const nlohmann::json& json, engine::Light::Type type) {
    try {
        shadowmap::checkFilterForType(shadowmap::parseSettings(json, kSource, kObject), type, kSource, kObject);
    } catch (const engine::InputError& error) {
        return error.what();
    }
    return "no error";
}
} // namespace

TEST(ShadowSettingsErrors, PcssOnALightWithoutASizeIsNamed) {
    using Type = engine::Light::Type;
    const auto messageFor = filterErrorFor;
    const std::string prefix = std::string(kSource) + ": " + kObject + ".filter: \"pcss\" softens the shadow by the "
                                                                      "light's size, and this light has none: set ";
    EXPECT_EQ(messageFor({{"filter", "pcss"}}, Type::Spot), prefix + "light_radius, or use filter \"pcf\"");
    EXPECT_EQ(messageFor({{"filter", "pcss"}}, Type::Directional),
              prefix + "angular_diameter (the sun: about 0.0093), or use filter \"pcf\"");
    // The other type's size does not count.
    EXPECT_NE(messageFor({{"filter", "pcss"}, {"angular_diameter", 0.01}}, Type::Point), "no error");
    EXPECT_EQ(messageFor({{"filter", "pcss"}, {"light_radius", 0.1}}, Type::Point), "no error");
    EXPECT_EQ(messageFor({{"filter", "pcss"}, {"angular_diameter", 0.01}}, Type::Directional), "no error");
    EXPECT_EQ(messageFor({{"filter", "pcss"}, {"variant", "none"}}, Type::Spot), "no error");
    // filter_radius widens pcf only: with another filter it would silently do nothing.
    const std::string radius = std::string(kSource) + ": " + kObject +
                               ".filter_radius: widens pcf's kernel and blurs vsm's and evsm's moments, and ";
    EXPECT_EQ(messageFor({{"filter", "nearest"}, {"filter_radius", 2}}, Type::Spot),
              radius + "this light's filter is \"nearest\": use filter \"pcf\", or filter_radius 0");
    EXPECT_NE(messageFor({{"filter", "pcss"}, {"light_radius", 0.1}, {"filter_radius", 2}}, Type::Spot), "no error");
    EXPECT_EQ(messageFor({{"filter", "pcf"}, {"filter_radius", 2}}, Type::Spot), "no error");
    EXPECT_EQ(messageFor({{"filter", "nearest"}, {"filter_radius", 0}}, Type::Spot), "no error");
    EXPECT_EQ(messageFor({{"filter", "vsm"}, {"filter_radius", 2}}, Type::Spot), "no error");
    EXPECT_EQ(messageFor({{"filter", "evsm"}, {"filter_radius", 2}}, Type::Point), "no error");
}

TEST(ShadowSettingsErrors, MomentsFiltersNeedALinearFiniteDepth) {
    using Type = engine::Light::Type;
    const auto messageFor = filterErrorFor;
    // lispsm's depth is not linear in the distance from the light.
    const std::string lispsm = messageFor({{"filter", "vsm"}, {"projection", "lispsm"}}, Type::Directional);
    EXPECT_NE(lispsm.find(std::string(kObject) + ".projection: \"lispsm\" warps"), std::string::npos) << lispsm;
    EXPECT_EQ(messageFor({{"filter", "evsm"}, {"projection", "lispsm"}, {"variant", "none"}}, Type::Directional),
              "no error");
    // A perspective map's moments are fractions of far - near: an infinite far has none.
    for (const nlohmann::json& infinite :
         {nlohmann::json{{"filter", "vsm"}, {"far_plane", "infinite"}},
          nlohmann::json{{"filter", "evsm"}, {"depth_format", "d32f"}, {"reversed_z", true}}}) {
        const std::string message = messageFor(infinite, Type::Point);
        EXPECT_NE(message.find(std::string(kObject) + ".far_plane: "), std::string::npos) << message;
        EXPECT_NE(message.find("set far_plane"), std::string::npos) << message;
    }
    EXPECT_EQ(messageFor({{"filter", "evsm"}, {"depth_format", "d32f"}, {"reversed_z", true}, {"far_plane", 40}},
                         Type::Spot),
              "no error");
    // A directional light's depth is linear and its far finite, whatever the settings.
    EXPECT_EQ(messageFor({{"filter", "vsm"}, {"depth_format", "d32f"}, {"reversed_z", true}}, Type::Directional),
              "no error");
}

TEST(ShadowSettingsErrors, PolygonOffsetIsTwoFiniteNumbers) {
    expectNamed({"one number", {{"polygon_offset", nlohmann::json::array({1.0})}}, "polygon_offset", "must be [factor, units]"});
    expectNamed({"not an array", {{"polygon_offset", 4}}, "polygon_offset", "must be [factor, units]"});
    expectNamed({"units text", {{"polygon_offset", {1.0, "x"}}}, "polygon_offset[1]", "must be a number"});
    expectNamed({"factor NaN", {{"polygon_offset", {kNaN, 4.0}}}, "polygon_offset[0]", "must be finite"});
}

TEST(ShadowSettingsErrors, CombinedKeysAreCheckedTogether) {
    expectNamed({"reversed_z with d24", {{"reversed_z", true}, {"depth_format", "d24"}}, "reversed_z",
                 "needs depth_format \"d32f\", not \"d24\""});
    expectNamed({"reversed_z by default format", {{"reversed_z", true}}, "reversed_z",
                 "needs depth_format \"d32f\", not \"d24\""});
    expectNamed({"near beyond far", {{"near_plane", 10}, {"far_plane", 5}}, "far_plane",
                 "must be beyond near_plane (10), got 5"});
    expectNamed({"near equal far", {{"near_plane", 2.5}, {"far_plane", 2.5}}, "far_plane",
                 "must be beyond near_plane (2.5), got 2.5"});
    expectNamed({"above the GL's limit", {{"resolution", 8192}}, "resolution",
                 "8192 is above this GL's GL_MAX_TEXTURE_SIZE 4096"});
    // A light without a shadow has no map to be too large.
    EXPECT_EQ(errorOf({{"resolution", 8192}, {"variant", "none"}}), "no error");
    EXPECT_EQ(errorOf({{"reversed_z", true}, {"depth_format", "d32f"}, {"near_plane", 0.5}, {"far_plane", "infinite"}}),
              "no error");
}

TEST(ShadowSettingsErrors, TheSettingsMustBeAnObject) {
    const std::string message = errorOf(nlohmann::json::array({1, 2}));
    EXPECT_EQ(message, std::string(kSource) + ": " + kObject + ": must be a JSON object");
}

TEST(ShadowSettingsErrors, ACommandLineVariantNamesItsFlag) {
    try {
        shadowmap::parseVariant("soft", "--light sun=soft", "variant");
        FAIL() << "no error";
    } catch (const engine::InputError& error) {
        EXPECT_STREQ(error.what(), "--light sun=soft: variant: unknown variant \"soft\" (known: standard, woo, "
                                   "backface, none, volume)");
    }
}

TEST(ShadowSettingsErrors, LispsmIsForDirectionalLightsHardFiltersAndAPositiveScale) {
    using Type = engine::Light::Type;
    expectNamed({"projection", {{"projection", "psm"}}, "projection",
                 "unknown projection \"psm\" (known: uniform, lispsm)"});
    for (const double bad : {0.0, -1.0})
        expectNamed({"lispsm_n_scale", {{"lispsm_n_scale", bad}}, "lispsm_n_scale", "must be a finite number > 0"});
    expectNamed({"lispsm_n_scale", {{"lispsm_n_scale", kInfinity}}, "lispsm_n_scale", "must be finite"});
    auto projectionMessage = [](const nlohmann::json& json, Type type) -> std::string {
        try {
            shadowmap::checkProjectionKeyForType(json, type, kSource, kObject);
        } catch (const engine::InputError& error) {
            return error.what();
        }
        return "no error";
    };
    for (Type type : {Type::Spot, Type::Point})
        EXPECT_EQ(projectionMessage({{"projection", "lispsm"}}, type),
                  std::string(kSource) + ": " + kObject +
                      ".projection: \"lispsm\" warps a directional light's map; a spot or point light's map is a "
                      "perspective already: use \"uniform\"");
    EXPECT_EQ(projectionMessage({{"projection", "uniform"}}, Type::Spot), "no error");
    EXPECT_EQ(projectionMessage({{"projection", "lispsm"}}, Type::Directional), "no error");

    // pcss's penumbra search reads an unwarped map: the pair is refused on a directional light
    // (where lispsm applies) and left alone on a spot light (where it does not).
    shadowmap::ShadowSettings settings =
        shadowmap::parseSettings({{"projection", "lispsm"}, {"filter", "pcss"}}, kSource, kObject);
    settings.angularDiameter = 0.01;
    settings.lightRadius = 0.1;
    try {
        shadowmap::checkFilterForType(settings, Type::Directional, kSource, kObject);
        ADD_FAILURE() << "lispsm with pcss was accepted";
    } catch (const engine::InputError& error) {
        EXPECT_NE(std::string(error.what()).find(std::string(kObject) + ".projection: \"lispsm\" warps the map"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_NO_THROW(shadowmap::checkFilterForType(settings, Type::Spot, kSource, kObject));
}

TEST(ShadowSettingsErrors, CasterLodIsAFiniteFractionAtLeastZero) {
    expectNamed({"caster_lod", {{"caster_lod", -0.5}}, "caster_lod", "must be a finite number >= 0"});
    for (const double bad : {kNaN, kInfinity})
        expectNamed({"caster_lod", {{"caster_lod", bad}}, "caster_lod", "must be finite"});
    expectNamed({"caster_lod", {{"caster_lod", "coarse"}}, "caster_lod", "must be a number"});
}
