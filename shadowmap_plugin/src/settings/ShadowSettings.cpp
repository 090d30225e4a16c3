// Reading and checking shadow settings (shadowmap/ShadowSettings.h): every bad value is an
// InputError naming the source, the light and the key, with the reason.
#include "shadowmap/ShadowSettings.h"

#include "settings/EnumNames.h"

#include "engine/util/Error.h"
#include "engine/util/FormatNumber.h"
#include "engine/util/JsonRead.h"

#include <cmath>
#include <limits>

namespace shadowmap {

namespace {

template <typename Enum, std::size_t N>
Enum parseEnum(const std::string& text, const char* const (&names)[N], const char* what,
               const std::string& source, const std::string& object) {
    std::string known;
    for (std::size_t i = 0; i < N; ++i) {
        if (text == names[i]) return static_cast<Enum>(i);
        known += (i ? ", " : "") + std::string(names[i]);
    }
    engine::throwInputError(source, object,
                            "unknown " + std::string(what) + " \"" + text + "\" (known: " + known + ")");
}

std::vector<std::string> keyNames() {
    std::vector<std::string> names;
    for (const SettingKey& key : settingKeys()) names.push_back(key.name);
    return names;
}

} // namespace

const char* toString(Variant variant) { return names::kVariants[static_cast<int>(variant)]; }
const char* toString(DepthFormat format) { return names::kDepthFormats[static_cast<int>(format)]; }
const char* toString(Filter filter) { return names::kFilters[static_cast<int>(filter)]; }
const char* toString(Projection projection) { return names::kProjections[static_cast<int>(projection)]; }

glm::vec2 defaultPolygonOffset(Variant variant, Filter filter, bool reversedZ) {
    if (variant != Variant::Standard) return glm::vec2(0.0f);
    // pcss's taps are 2x2 bilinear comparisons, like pcf's one tap; vsm's and evsm's moments
    // are read bilinearly too, and an offset map keeps a receiver's mean behind it.
    return glm::vec2(filter == Filter::Nearest ? 1.0f : 2.0f, reversedZ ? 128.0f : 8.0f);
}

Variant parseVariant(const std::string& text, const std::string& source, const std::string& object) {
    return parseEnum<Variant>(text, names::kVariants, "variant", source, object);
}

void applySettings(ShadowSettings& settings, const nlohmann::json& json, const std::string& source,
                   const std::string& object) {
    namespace json_read = engine::json;
    static const std::vector<std::string> known = keyNames();
    json_read::requireKnownKeys(json, known, source, object);
    const auto key = [&](const char* name) { return object + "." + name; };
    if (json.contains("variant"))
        settings.variant = parseVariant(json_read::readString(json["variant"], source, key("variant")),
                                        source, key("variant"));
    if (json.contains("resolution")) {
        const double resolution = json_read::readNumber(json["resolution"], source, key("resolution"));
        if (resolution < 1.0 || resolution != std::floor(resolution))
            engine::throwInputError(source, key("resolution"),
                                    "must be a whole number of texels >= 1, got " +
                                        json["resolution"].dump());
        // Beyond any GL's texture size; checkLimits() compares with this GL's own limit.
        static const double bound = *settingKey("resolution").maximum;
        if (resolution > bound)
            engine::throwInputError(source, key("resolution"),
                                    json["resolution"].dump() + " texels is beyond any GL_MAX_TEXTURE_SIZE");
        settings.resolution = static_cast<int>(resolution);
    }
    if (json.contains("depth_format"))
        settings.depthFormat = parseEnum<DepthFormat>(
            json_read::readString(json["depth_format"], source, key("depth_format")), names::kDepthFormats,
            "depth format", source, key("depth_format"));
    if (json.contains("filter"))
        settings.filter =
            parseEnum<Filter>(json_read::readString(json["filter"], source, key("filter")),
                              names::kFilters, "filter", source, key("filter"));
    if (json.contains("filter_taps")) {
        const double taps = json_read::readNumber(json["filter_taps"], source, key("filter_taps"));
        if (taps < kMinFilterTaps || taps > kMaxFilterTaps || taps != std::floor(taps))
            engine::throwInputError(source, key("filter_taps"),
                                    "must be a whole number in [" + std::to_string(kMinFilterTaps) + ", " +
                                        std::to_string(kMaxFilterTaps) + "], got " + json["filter_taps"].dump());
        settings.filterTaps = static_cast<int>(taps);
    }
    // A length in texels, 0 .. maximum.
    const auto readTexels = [&](const char* name, double maximum) {
        const double texels = json_read::readNumber(json[name], source, key(name));
        if (texels < 0.0 || texels > maximum)
            engine::throwInputError(source, key(name),
                                    "must be in [0, " + engine::formatNumber(maximum) + "] texels, got " +
                                        json[name].dump());
        return texels;
    };
    if (json.contains("filter_radius")) settings.filterRadius = readTexels("filter_radius", kMaxFilterRadius);
    if (json.contains("normal_offset")) settings.normalOffset = readTexels("normal_offset", kMaxNormalOffset);
    if (json.contains("polygon_offset")) {
        const auto& offset = json["polygon_offset"];
        if (!offset.is_array() || offset.size() != 2)
            engine::throwInputError(source, key("polygon_offset"), "must be [factor, units]");
        settings.polygonOffset = glm::vec2(
            static_cast<float>(json_read::readNumber(offset[0], source, key("polygon_offset") + "[0]")),
            static_cast<float>(json_read::readNumber(offset[1], source, key("polygon_offset") + "[1]")));
    }
    if (json.contains("dimming")) {
        const double dimming = json_read::readNumber(json["dimming"], source, key("dimming"));
        static const SettingKey& range = settingKey("dimming");
        if (dimming < *range.minimum || dimming > *range.maximum)
            engine::throwInputError(source, key("dimming"),
                                    "must be in [" + engine::formatNumber(*range.minimum) + ", " +
                                        engine::formatNumber(*range.maximum) + "], got " + json["dimming"].dump());
        settings.dimming = static_cast<float>(dimming);
    }
    // Frustum overrides and precision: world distances along the light's axis.
    if (json.contains("near_plane")) {
        const double nearPlane = json_read::readNumber(json["near_plane"], source, key("near_plane"));
        if (!(nearPlane > 0.0))
            engine::throwInputError(source, key("near_plane"),
                                    "must be a distance > 0, got " + json["near_plane"].dump());
        settings.nearPlane = nearPlane;
    }
    if (json.contains("far_plane")) {
        if (json["far_plane"] == "infinite") {
            settings.farPlane = std::numeric_limits<double>::infinity();
        } else {
            if (!json["far_plane"].is_number())
                engine::throwInputError(source, key("far_plane"),
                                        "must be a distance > 0 or \"infinite\", got " + json["far_plane"].dump());
            const double farPlane = json_read::readNumber(json["far_plane"], source, key("far_plane"));
            if (!(farPlane > 0.0))
                engine::throwInputError(source, key("far_plane"),
                                        "must be a distance > 0 or \"infinite\", got " + json["far_plane"].dump());
            settings.farPlane = farPlane;
        }
    }
    if (json.contains("reversed_z"))
        settings.reversedZ = json_read::readBool(json["reversed_z"], source, key("reversed_z"));
    if (json.contains("polygon_offset_clamp")) {
        const double clamp = json_read::readNumber(json["polygon_offset_clamp"], source, key("polygon_offset_clamp"));
        if (clamp < 0.0)
            engine::throwInputError(source, key("polygon_offset_clamp"),
                                    "must be a slope >= 0 (0: unclamped), got " + json["polygon_offset_clamp"].dump());
        settings.polygonOffsetClamp = static_cast<float>(clamp);
    }
    if (json.contains("cascades")) {
        static const SettingKey& range = settingKey("cascades");
        const std::string expected = "must be \"auto\" or a whole number in [" + engine::formatNumber(*range.minimum) +
                                     ", " + engine::formatNumber(*range.maximum) + "], got " + json["cascades"].dump();
        if (json["cascades"] == "auto") {
            settings.cascades = kAutoCascades;
        } else {
            if (!json["cascades"].is_number()) engine::throwInputError(source, key("cascades"), expected);
            const double cascades = json_read::readNumber(json["cascades"], source, key("cascades"));
            if (cascades < *range.minimum || cascades > *range.maximum || cascades != std::floor(cascades))
                engine::throwInputError(source, key("cascades"), expected);
            settings.cascades = static_cast<int>(cascades);
        }
    }
    if (json.contains("cascade_blend")) {
        const double blend = json_read::readNumber(json["cascade_blend"], source, key("cascade_blend"));
        if (blend < 0.0 || blend > 0.5)
            engine::throwInputError(source, key("cascade_blend"),
                                    "must be in [0, 0.5], got " + json["cascade_blend"].dump());
        settings.cascadeBlend = blend;
    }
    if (json.contains("cascade_lambda")) {
        const double lambda = json_read::readNumber(json["cascade_lambda"], source, key("cascade_lambda"));
        if (lambda < 0.0 || lambda > 1.0)
            engine::throwInputError(source, key("cascade_lambda"),
                                    "must be in [0, 1], got " + json["cascade_lambda"].dump());
        settings.cascadeLambda = lambda;
    }
    if (json.contains("stable")) settings.stable = json_read::readBool(json["stable"], source, key("stable"));
    if (json.contains("cull_unseen_casters"))
        settings.cullUnseenCasters = json_read::readBool(json["cull_unseen_casters"], source, key("cull_unseen_casters"));
    if (json.contains("shadow_distance")) {
        const double distance = json_read::readNumber(json["shadow_distance"], source, key("shadow_distance"));
        if (!(distance >= 0.0) || !std::isfinite(distance))
            engine::throwInputError(source, key("shadow_distance"),
                                    "must be a finite number >= 0 (0: no limit), got " + json["shadow_distance"].dump());
        settings.shadowDistance = distance;
    }
    if (json.contains("shadow_fade")) {
        const double fade = json_read::readNumber(json["shadow_fade"], source, key("shadow_fade"));
        if (!(fade >= 0.0 && fade <= 1.0))
            engine::throwInputError(source, key("shadow_fade"), "must be in [0, 1], got " + json["shadow_fade"].dump());
        settings.shadowFade = fade;
    }
    const auto readSize = [&](const char* name, const char* unit) {
        const double size = json_read::readNumber(json[name], source, key(name));
        if (size < 0.0)
            engine::throwInputError(source, key(name),
                                    std::string("must be >= 0 ") + unit + " (0: no size), got " + json[name].dump());
        return size;
    };
    if (json.contains("projection"))
        settings.projection =
            parseEnum<Projection>(json_read::readString(json["projection"], source, key("projection")),
                                  names::kProjections, "projection", source, key("projection"));
    if (json.contains("lispsm_n_scale")) {
        const double scale = json_read::readNumber(json["lispsm_n_scale"], source, key("lispsm_n_scale"));
        if (!(scale > 0.0) || !std::isfinite(scale))
            engine::throwInputError(source, key("lispsm_n_scale"),
                                    "must be a finite number > 0 (1: the optimal n), got " +
                                        json["lispsm_n_scale"].dump());
        settings.lispsmNScale = scale;
    }
    if (json.contains("caster_lod")) {
        const double fraction = json_read::readNumber(json["caster_lod"], source, key("caster_lod"));
        if (!(fraction >= 0.0) || !std::isfinite(fraction))
            engine::throwInputError(source, key("caster_lod"),
                                    "must be a finite number >= 0 (a fraction of a texel; 0: off), got " +
                                        json["caster_lod"].dump());
        settings.casterLod = fraction;
    }
    if (json.contains("bleed_reduction")) {
        const double reduction = json_read::readNumber(json["bleed_reduction"], source, key("bleed_reduction"));
        if (!(reduction >= 0.0 && reduction <= kMaxBleedReduction))
            engine::throwInputError(source, key("bleed_reduction"),
                                    "must be in [0, " + engine::formatNumber(kMaxBleedReduction) + "], got " +
                                        json["bleed_reduction"].dump());
        settings.bleedReduction = reduction;
    }
    if (json.contains("evsm_exponents")) {
        const auto& exponents = json["evsm_exponents"];
        const std::string expected = "must be [positive, negative], each in (0, " +
                                     engine::formatNumber(kMaxEvsmExponent) + "] (e^(2c) in 32-bit float), got " +
                                     exponents.dump();
        if (!exponents.is_array() || exponents.size() != 2)
            engine::throwInputError(source, key("evsm_exponents"), expected);
        glm::vec2 value;
        for (int i = 0; i < 2; ++i) {
            const double c = json_read::readNumber(exponents[i], source, key("evsm_exponents") + "[" + std::to_string(i) + "]");
            if (!(c > 0.0 && c <= kMaxEvsmExponent)) engine::throwInputError(source, key("evsm_exponents"), expected);
            value[i] = static_cast<float>(c);
        }
        settings.evsmExponents = value;
    }
    if (json.contains("moments_mipmaps"))
        settings.momentsMipmaps = json_read::readBool(json["moments_mipmaps"], source, key("moments_mipmaps"));
    if (json.contains("light_radius")) settings.lightRadius = readSize("light_radius", "world units");
    if (json.contains("angular_diameter")) settings.angularDiameter = readSize("angular_diameter", "radians");
}

void checkSizeKeyForType(const nlohmann::json& json, engine::Light::Type type, const std::string& source,
                         const std::string& object) {
    const bool directional = type == engine::Light::Type::Directional;
    const char* wrongKey = directional ? "light_radius" : "angular_diameter";
    if (json.is_object() && json.contains(wrongKey))
        engine::throwInputError(source, object + "." + wrongKey,
                                directional ? "a directional light has no radius: size it with angular_diameter"
                                            : "a spot or point light has no angular diameter: size it with "
                                              "light_radius");
}

void checkProjectionKeyForType(const nlohmann::json& json, engine::Light::Type type, const std::string& source,
                               const std::string& object) {
    if (type == engine::Light::Type::Directional || !json.is_object() || !json.contains("projection")) return;
    if (json["projection"] == toString(Projection::Lispsm))
        engine::throwInputError(source, object + ".projection",
                                "\"lispsm\" warps a directional light's map; a spot or point light's map is a "
                                "perspective already: use \"uniform\"");
}

void checkFilterForType(const ShadowSettings& settings, engine::Light::Type type, const std::string& source,
                        const std::string& object) {
    if (settings.variant == Variant::None) return;
    if (settings.filterRadius > 0.0 && settings.filter != Filter::Pcf && !readsMoments(settings.filter))
        engine::throwInputError(source, object + ".filter_radius",
                                std::string("widens pcf's kernel and blurs vsm's and evsm's moments, and this light's "
                                            "filter is \"") +
                                    toString(settings.filter) + "\": use filter \"pcf\", or filter_radius 0");
    const bool directional = type == engine::Light::Type::Directional;
    if (readsMoments(settings.filter)) {
        if (directional && settings.projection == Projection::Lispsm)
            engine::throwInputError(source, object + ".projection",
                                    std::string("\"lispsm\" warps the map's depth along its warp axis, and \"") +
                                        toString(settings.filter) +
                                        "\" filters depth linear in the distance from the light: use projection "
                                        "\"uniform\" with it");
        // A perspective map's moments hold the distance from near as a fraction of far - near.
        const bool infiniteFar = std::isinf(settings.farPlane) || (settings.reversedZ && settings.farPlane == 0.0);
        if (!directional && infiniteFar)
            engine::throwInputError(source, object + ".far_plane",
                                    std::string("\"") + toString(settings.filter) +
                                        "\" stores the distance from the light as a fraction of far - near, and this "
                                        "light's far plane is infinite (reversed_z's default): set far_plane");
    }
    if (directional && settings.projection == Projection::Lispsm && settings.filter == Filter::Pcss)
        engine::throwInputError(source, object + ".projection",
                                "\"lispsm\" warps the map, and pcss's penumbra search assumes an unwarped one: use "
                                "projection \"uniform\" with pcss, or a hard filter (\"pcf\", \"nearest\")");
    if (settings.filter != Filter::Pcss || settings.lightSize(type) > 0.0) return;
    engine::throwInputError(source, object + ".filter",
                            std::string("\"pcss\" softens the shadow by the light's size, and this light has none: "
                                        "set ") +
                                (directional ? "angular_diameter (the sun: about 0.0093)" : "light_radius") +
                                ", or use filter \"pcf\"");
}

ShadowSettings parseSettings(const nlohmann::json& json, const std::string& source, const std::string& object) {
    ShadowSettings settings;
    applySettings(settings, json, source, object);
    return settings;
}

void checkLimits(const ShadowSettings& settings, int maxTextureSize, const std::string& source,
                 const std::string& object) {
    if (settings.variant != Variant::None && settings.resolution > maxTextureSize)
        engine::throwInputError(source, object + ".resolution",
                                std::to_string(settings.resolution) +
                                    " is above this GL's GL_MAX_TEXTURE_SIZE " +
                                    std::to_string(maxTextureSize));
    if (settings.reversedZ && settings.depthFormat != DepthFormat::D32F)
        engine::throwInputError(source, object + ".reversed_z",
                                std::string("needs depth_format \"d32f\", not \"") +
                                    toString(settings.depthFormat) +
                                    "\" (fixed-point depth gains nothing from the reversal)");
    if (settings.nearPlane > 0.0 && settings.farPlane > 0.0 && !(settings.farPlane > settings.nearPlane))
        engine::throwInputError(source, object + ".far_plane",
                                "must be beyond near_plane (" + engine::formatNumber(settings.nearPlane) +
                                    "), got " + engine::formatNumber(settings.farPlane));
}

} // namespace shadowmap
