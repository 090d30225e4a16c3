#pragma once
// Per-light shadow settings and where they come from, most specific last:
//   built-in defaults  <-  plugin settings in the engine config  <-  the light's glTF
//   extras.shadow  <-  engine-render --light NAME=VARIANT.
// Every key and value is checked: an unknown key, variant, format or filter, a resolution
// of 0 or above GL_MAX_TEXTURE_SIZE, a non-finite number or a dimming outside [0,1] is an
// InputError naming the source (config file or scene), the light and the key.
//
//   key             values                               default
//   variant         "standard" | "woo" | "backface" | "none"   "standard"
//   resolution      1 .. GL_MAX_TEXTURE_SIZE (texels/side)     2048
//   depth_format    "d16" | "d24" | "d32f"                     "d24"
//   filter          "nearest" (1 tap) | "pcf" (2x2 bilinear)   "pcf"
//   polygon_offset  [factor, units] of the depth pass           standard: [1.0, 8.0]
//                                                              nearest, [2.0, 8.0] pcf;
//                                                              woo, backface: none
// woo and backface need no tuned offset (that is their point); backface still draws open
// casters two-sided, with the standard offset.
// The default offset departs from the seeds' (1, 4), for measured reasons:
//  - units 8, not 4: the comparison's reference r/q is computed in float32, whose spacing
//    near depth 1 is 2^-24, one d24 unit; with 4 units a floor facing a spot light head-on
//    (zero slope, so only units help) showed acne lines on 2.2% of its lit pixels (d24 and
//    d32f alike, any map size), with 8 units none (tests/shadowmap/render/ShadowMaskTest);
//  - factor 2 with pcf: a one-tap lookup is at most half a texel from the texel centre,
//    but 2x2 PCF also compares the neighbouring texels, one full texel of slope further;
//    with factor 1 it showed acne on 14-18% of the showcase's lit pixels (spot and sun).
// An explicit polygon_offset is used as is.
//   dimming         d in [0,1]: shadowed diffuse keeps d       0.4
#include "engine/graph/TextureDesc.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <optional>

#include <string>

namespace shadowmap {

enum class Variant { Standard, Woo, Backface, None };
enum class DepthFormat { D16, D24, D32F };
enum class Filter { Nearest, Pcf };

const char* toString(Variant);
const char* toString(DepthFormat);
const char* toString(Filter);

struct ShadowSettings {
    Variant variant = Variant::Standard;
    int resolution = 2048;
    DepthFormat depthFormat = DepthFormat::D24;
    Filter filter = Filter::Pcf;
    std::optional<glm::vec2> polygonOffset;  // unset: the variant's default

    // The offset a two-sided depth draw needs: the explicit one, else the filter's default.
    glm::vec2 standardPolygonOffset() const {
        return polygonOffset ? *polygonOffset
                             : glm::vec2(filter == Filter::Pcf ? 2.0f : 1.0f, 8.0f);
    }
    // The offset of this light's depth pass.
    glm::vec2 effectivePolygonOffset() const {
        if (variant == Variant::Standard) return standardPolygonOffset();
        return polygonOffset ? *polygonOffset : glm::vec2(0.0f);
    }
    float dimming = 0.4f;

    bool operator==(const ShadowSettings&) const = default;
};

// Applies the keys of `json` (an object) over `settings`. `source` and `object` name where
// the JSON came from for messages, e.g. ("scene.gltf", "light \"sun\": extras.shadow").
void applySettings(ShadowSettings& settings, const nlohmann::json& json, const std::string& source,
                   const std::string& object);

Variant parseVariant(const std::string& text, const std::string& source, const std::string& object);

// Checks what depends on the GL implementation (the resolution limit).
void checkLimits(const ShadowSettings& settings, int maxTextureSize, const std::string& source,
                 const std::string& object);

unsigned glInternalFormat(DepthFormat format);
// The depth step of a format near 1 (fixed point: 1/(2^bits - 1); d32f: 2^-24).
double depthStep(DepthFormat format);
engine::TextureFormat graphFormat(DepthFormat format);

} // namespace shadowmap
