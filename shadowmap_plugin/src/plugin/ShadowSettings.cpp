#include "plugin/ShadowSettings.h"

#include "engine/util/Error.h"
#include "engine/util/FormatNumber.h"
#include "engine/util/JsonRead.h"

#include <epoxy/gl.h>

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

constexpr const char* kVariantNames[] = {"standard", "woo", "backface", "none"};
constexpr const char* kFormatNames[] = {"d16", "d24", "d32f"};
constexpr const char* kFilterNames[] = {"nearest", "pcf"};

} // namespace

const char* toString(Variant variant) { return kVariantNames[static_cast<int>(variant)]; }
const char* toString(DepthFormat format) { return kFormatNames[static_cast<int>(format)]; }
const char* toString(Filter filter) { return kFilterNames[static_cast<int>(filter)]; }

Variant parseVariant(const std::string& text, const std::string& source, const std::string& object) {
    return parseEnum<Variant>(text, kVariantNames, "variant", source, object);
}

void applySettings(ShadowSettings& settings, const nlohmann::json& json, const std::string& source,
                   const std::string& object) {
    namespace json_read = engine::json;
    json_read::requireKnownKeys(json,
                                {"variant", "resolution", "depth_format", "filter",
                                 "polygon_offset", "dimming", "near_plane", "far_plane",
                                 "reversed_z", "polygon_offset_clamp"},
                                source, object);
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
        if (resolution > 1 << 20)
            engine::throwInputError(source, key("resolution"),
                                    json["resolution"].dump() + " texels is beyond any GL_MAX_TEXTURE_SIZE");
        settings.resolution = static_cast<int>(resolution);
    }
    if (json.contains("depth_format"))
        settings.depthFormat = parseEnum<DepthFormat>(
            json_read::readString(json["depth_format"], source, key("depth_format")), kFormatNames,
            "depth format", source, key("depth_format"));
    if (json.contains("filter"))
        settings.filter =
            parseEnum<Filter>(json_read::readString(json["filter"], source, key("filter")),
                              kFilterNames, "filter", source, key("filter"));
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
        if (dimming < 0.0 || dimming > 1.0)
            engine::throwInputError(source, key("dimming"), "must be in [0, 1], got " + json["dimming"].dump());
        settings.dimming = static_cast<float>(dimming);
    }
    // Frustum overrides and precision (issue 8): world distances along the light's axis.
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

unsigned glInternalFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return GL_DEPTH_COMPONENT16;
    case DepthFormat::D24: return GL_DEPTH_COMPONENT24;
    case DepthFormat::D32F: return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT24;
}

double depthStep(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return 1.0 / 65535.0;
    case DepthFormat::D24: return 1.0 / 16777215.0;
    case DepthFormat::D32F: return std::ldexp(1.0, -24);
    }
    return 1.0 / 16777215.0;
}

engine::TextureFormat graphFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return engine::TextureFormat::Depth16;
    case DepthFormat::D24: return engine::TextureFormat::Depth24;
    case DepthFormat::D32F: return engine::TextureFormat::Depth32F;
    }
    return engine::TextureFormat::Depth24;
}

} // namespace shadowmap
