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
//   polygon_offset  [factor, units] (standard variant)         [1.0, 4.0] nearest,
//                                                              [2.0, 4.0] pcf
// The default offset follows the filter: the seeds' (1, 4) covers a one-tap lookup, which
// is at most half a texel from the texel centre; 2x2 PCF also compares the neighbouring
// texels, one full texel of depth slope further, and with (1, 4) it showed acne on 14-18%
// of the showcase's lit pixels (spot and sun, d24, 2048). An explicit value is used as is.
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
    std::optional<glm::vec2> polygonOffset;  // unset: the filter's default
    glm::vec2 effectivePolygonOffset() const {
        return polygonOffset ? *polygonOffset
                             : glm::vec2(filter == Filter::Pcf ? 2.0f : 1.0f, 4.0f);
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
engine::TextureFormat graphFormat(DepthFormat format);

} // namespace shadowmap
