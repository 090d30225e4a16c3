#pragma once
// The shadow plugin's per-light settings, public: one home for what a setting is, its
// default, the values it accepts, how it is read from JSON and written back. The plugin
// module resolves every light through it; the tools (engine-view, shadowmap-bench,
// shadowmap-stress) ask it for defaults and allowed values instead of repeating them, and
// the README's settings table is checked against settingKeys() by a test.
// No GL here: the GL side of a depth format lives with the plugin (technique/DepthFormatGl.h).
//
// Per-light shadow settings and where they come from, most specific last:
//   built-in defaults  <-  plugin settings in the engine config (--set PLUGIN.KEY=JSON edits
//   them)  <-  the light's glTF extras.shadow  <-  engine-render --light-set NAME.KEY=JSON
//   (--light NAME=VARIANT is --light-set NAME.variant=VARIANT).
// Every key and value is checked: an unknown key, variant, format or filter, a resolution
// of 0 or above GL_MAX_TEXTURE_SIZE, a non-finite number or a dimming outside [0,1] is an
// InputError naming the source (config file or scene), the light and the key.
//
//   key             values                               default
//   variant         "standard" | "woo" | "backface" | "none" | "volume"   "standard"
//   resolution      1 .. GL_MAX_TEXTURE_SIZE (texels/side)     2048
//   depth_format    "d16" | "d24" | "d32f"                     "d24"
//   filter          "nearest" (1 tap) | "pcf" (2x2 bilinear)   "pcf"
//                   | "pcss" (percentage-closer soft shadows from the light's size: a blocker
//                   search, then a filter as wide as the penumbra; needs a light size)
//                   | "vsm" | "evsm" (filterable maps: variance, or exponential variance,
//                   moments of the light-linear depth, made from the depth map after its
//                   passes, blurred by filter_radius, mipmapped (2D maps), read with one
//                   filtered fetch and Chebyshev's bound; technique/lookup/MomentsLookup.h)
//   filter_taps     4 .. 64: pcss's and wide pcf's taps (each     16
//                   a 2x2 bilinear comparison); pcss's blocker search takes half as many
//   filter_radius   0 .. 16 texels: pcf over a disk of this       0 (one 2x2 tap)
//                   radius (filter_taps rotated taps) instead of one 2x2 tap; vsm and
//                   evsm: the moments' separable box blur, this many texels each side
//   bleed_reduction 0 .. 0.95: vsm, evsm: the share of Chebyshev's  0.3
//                   bound cut off as light bleeding (the rest stretched to [0, 1])
//   evsm_exponents  [positive, negative], each in (0, 40]: evsm's  [40, 5]
//                   depth warps e^(c u) and -e^(-c u) (ShadowLimits.h says why 40)
//   moments_mipmaps true: vsm and evsm 2D maps (spot, one            false
//                   directional map) are mipmapped and read trilinearly, anisotropically
//                   where the GL can; cascades and cube maps read their first level. Off
//                   by default: on the showcase the coarser levels softened edges into
//                   9x the spot's and 4x the sun's error (docs/filterable-maps.md)
//   normal_offset   0 .. 8 texels: the lookup moves the receiver  0.25
//                   along its normal by this many texels of the map at the receiver,
//                   times the sine of the light's angle to the normal (none facing the
//                   light, most at grazing light, where acne lives); every variant. The
//                   default had the least acne + leak summed over the showcase, masked,
//                   outdoor and 2CylinderEngine scenes, and worsened none (docs/soft-shadows.md)
//   polygon_offset  [factor, units] of the depth pass           standard: [1.0, 8.0]
//                                                              nearest, [2.0, 8.0] pcf;
//                                                              woo, backface: none
// woo and backface need no tuned offset (that is their point); backface still draws open
// casters two-sided, with the standard offset. An explicit offset on woo applies to both
// of its passes alike (the peel compares them): on the showcase it lowered woo's error
// (sun at 2048: 0.079% without, 0.034% with [2, 8]; at 512: 0.264%, 0.135% with [1, 2]).
// The default offset departs from the classic glPolygonOffset(1, 4) of the hardware
// shadow-mapping literature, for measured reasons:
//  - units 8, not 4: the comparison's reference r/q is computed in float32, whose spacing
//    near depth 1 is 2^-24, one d24 unit; with 4 units a floor facing a spot light head-on
//    (zero slope, so only units help) showed acne lines on 2.2% of its lit pixels (d24 and
//    d32f alike, any map size), with 8 units none (tests/shadowmap/render/ShadowMaskTest);
//  - factor 2 with pcf: a one-tap lookup is at most half a texel from the texel centre,
//    but 2x2 PCF also compares the neighbouring texels, one full texel of slope further;
//    with factor 1 it showed acne on 14-18% of the showcase's lit pixels (spot and sun).
// An explicit polygon_offset is used as is.
//   dimming         d in [0,1]: shadowed diffuse keeps d       0.4
// Numerical range and precision (measured by tools/shadowmap-stress):
//   near_plane      > 0, world units: the light frustum's near  fitted (nearest caster or
//                   distance instead of the fitted one (spot,  receiver in the frustum, at
//                   point; directional lights ignore it with   least far * 1e-4)
//                   a warning: their depth is linear)
//   far_plane       > near_plane, world units, or "infinite";  fitted (farthest receiver);
//                   spot and point, as near_plane               reversed_z: infinite
//   reversed_z      true: the depth pass runs with                false
//                   glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), a projection mapping
//                   near -> 1 and far (or infinity) -> 0, clear depth 0, GL_GREATER depth
//                   test and GL_GEQUAL comparison; texgen's S then leaves r as it is
//                   (s, t still scale-bias). Float depth keeps its relative precision
//                   where the depths are (n/d), so near/far = 1e-7 and an infinite far
//                   still resolve. Unless far_plane is set, the far plane is infinite:
//                   a finite far drives depth to 0 near it, where the lookup's absolute
//                   errors outgrow float's relative offset units (6% acne measured).
//                   Only with depth_format "d32f" (an error otherwise: fixed-point depth
//                   gains nothing from the reversal). The default polygon_offset units
//                   are then 128: a float unit is 2^(e-23) of the depth itself, so 128
//                   units are 1.5e-5 of the distance to the light (0.15 mm at 10 m);
//                   with 8, a point light on the floor showed 1.8% acne along its cube
//                   seams, with 128 0.01% (the fixed-point formats' 8 units, at a near
//                   plane of 1e-4 of the far, are millimetres there).
//   polygon_offset_clamp  S >= 0: the slope-scaled part of the    0 (unclamped)
//                   polygon offset stops growing at slope S (tan of the angle between the
//                   surface normal and the light), through glPolygonOffsetClamp: at
//                   grazing angles factor * slope becomes huge and pushes a caster's
//                   depth behind what it should shadow. The clamp is converted to window
//                   depth per light from its texel size and depth range at the nearest
//                   receiver (see DepthPassStyle::offsetClamp), so it means the same at
//                   any scene scale. Default 0: in the stress sweep no leak comes from the
//                   unclamped slope term, while a clamp puts acne on grazing receivers
//                   (spot at 0.5 deg: 0.30% error unclamped, 0.61% with S = 10, 19% with
//                   S = 3; tools/shadowmap-stress elevation).
//   cull_unseen_casters  true: a caster whose shadow can fall on   true
//                   no receiver the camera sees is left out of the depth passes (same
//                   image; technique/UnseenShadows.h). woo maps keep every caster
//   projection      "uniform" | "lispsm": a directional light's     "uniform"
//                   map orthographic, or warped by a light-space perspective so texels
//                   crowd near the camera (math/LispsmWarp.h); with cascades each is
//                   warped around its slice, fitted (a warp follows the camera, so
//                   `stable` does not apply), and cascades "auto" keeps one warped
//                   map. Set on a spot or point
//                   light's own settings it is an error (their maps are perspective
//                   already); in the plugin's defaults it applies to directional lights.
//                   Hard filters only (pcss with lispsm is an error)
//   lispsm_n_scale  > 0: multiplies LiSPSM's optimal n; above 1     1
//                   the warp weakens toward uniform, below 1 it magnifies the near end more
//   caster_lod      >= 0, a fraction of a texel: the depth passes   0 (off)
//                   draw each caster's coarsest simplified level (math/CasterLod.h) whose
//                   recorded error, at the instance's scale, is below caster_lod times the
//                   world size of one of this light's texels at the caster's nearest point
//                   (technique/CasterLodChoice.h). 0 draws every caster as loaded
// Cascades (directional lights only; spot and point lights ignore them):
//   cascades        auto, or 1 .. 4 slices of the camera's view  auto
//                   depth, one array layer (and depth pass) each; 1: one map fitted to
//                   every visible receiver; auto: the count the view needs, per frame
//                   (math/CascadeFit.h autoCascadeCount)
//   cascade_blend   0 .. 0.5: the band past each split, as a     0 (hard switch)
//                   fraction of the nearer cascade's depth range, over which the lookup
//                   fades from that cascade into the next (which then also covers the band)
//   cascade_lambda  0 .. 1: the practical split scheme's weight  0.75
//                   of logarithmic over uniform splits (math/CascadeFit.h)
//   stable          true: each cascade a texel-snapped square    true
//                   around its slice's bounding sphere, so a moving camera moves shadows
//                   in whole texels (costs up to 2x the texel size of a fitted cascade)
//   shadow_distance >= 0, world units: the view depth (along     0 (every visible
//                   the camera's -Z) where the light's shadows end; its   receiver)
//                   maps cover no farther, so their texels shrink with it (even one
//                   cascade is then a slice of the view); past it every point is lit
//   shadow_fade     0 .. 1: the last fraction of shadow_distance  0.1
//                   over which shadows fade out, so they end without a visible line
// A light's size (soft shadows; the truth samples the whole light):
//   light_radius    >= 0, world units: a spot or point light is   0 (a point)
//                   a disk of this radius facing the shaded point
//   angular_diameter >= 0, radians: a directional light is a      0 (a direction)
//                   cone of this apex angle (the sun: about 0.0093)
// Set per light, a size on the other type of light is an error naming light and key; set in
// the plugin's defaults, each applies to the lights of its type. A hard filter (nearest,
// pcf) keeps a sized light's hard shadow: the evaluation scores it against the soft truth.
// Biases are in depth-format units and texels, never world units: polygon_offset units are
// steps of the format (d16, d24: 1/(2^bits - 1); d32f: 2^(e-23) of the depth e); factor
// multiplies the depth slope per texel. d32f without reversed_z: the comparison's reference
// depth is computed in float as a difference near 1, so its error is absolute (about 2^-24)
// while float polygon-offset units shrink with the depth; the lookup then subtracts
// units * 2^-24 from the reference (the d24 meaning of units) so depths below 0.5 keep
// their bias.
#include <glm/glm.hpp>
#include "shadowmap/ShadowLimits.h"

#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowmap {

// volume: stenciled shadow volumes (exact hard shadows, no map; plugin/VolumePasses.h).
enum class Variant { Standard, Woo, Backface, None, Volume };
enum class DepthFormat { D16, D24, D32F };
enum class Filter { Nearest, Pcf, Pcss, Vsm, Evsm };
enum class Projection { Uniform, Lispsm };

// The names the JSON uses ("standard", "d24", "pcf").
const char* toString(Variant);
const char* toString(DepthFormat);
const char* toString(Filter);
const char* toString(Projection);

// vsm and evsm read a filterable map of depth moments (technique/lookup/MomentsLookup.h)
// made from the depth map, blurred by filter_radius, instead of comparing depths.
inline bool readsMoments(Filter filter) { return filter == Filter::Vsm || filter == Filter::Evsm; }

// The polygon offset [factor, units] a depth pass uses when none is explicit (see the
// table above): standard: units 8 (128 with reversed Z), factor 1 for one tap and 2 for
// PCF; woo, backface and none: no offset.
glm::vec2 defaultPolygonOffset(Variant variant, Filter filter, bool reversedZ);

// Default-constructed: the built-in defaults (the table above).
// The plugin's one name, in configs ("library"), messages, --stats and --set: the library's,
// since that is the name users type.
inline constexpr char kPluginName[] = "shadowmap_plugin";

// ShadowSettings::cascades for "auto".
inline constexpr int kAutoCascades = 0;

struct ShadowSettings {
    Variant variant = Variant::Standard;
    int resolution = kDefaultResolution;
    DepthFormat depthFormat = DepthFormat::D24;
    Filter filter = Filter::Pcf;
    std::optional<glm::vec2> polygonOffset;  // unset: the variant's default
    int filterTaps = 16;
    double filterRadius = 0.0;  // texels; 0: pcf's one 2x2 tap
    double normalOffset = 0.25;  // texels of the map at the receiver, times sin(normal, light)
    // vsm, evsm (see the table above): the light-bleeding reduction, EVSM's exponents and
    // whether a 2D map's moments are mipmapped.
    double bleedReduction = kDefaultBleedReduction;
    glm::vec2 evsmExponents{kDefaultEvsmExponents[0], kDefaultEvsmExponents[1]};
    bool momentsMipmaps = false;

    // The offset a two-sided depth draw needs: the explicit one, else the standard
    // variant's default for this filter and depth direction.
    glm::vec2 standardPolygonOffset() const {
        return polygonOffset ? *polygonOffset : defaultPolygonOffset(Variant::Standard, filter, reversedZ);
    }
    // The offset of this light's depth pass.
    glm::vec2 effectivePolygonOffset() const {
        return polygonOffset ? *polygonOffset : defaultPolygonOffset(variant, filter, reversedZ);
    }
    float dimming = 0.4f;
    // See the table above. 0 = fitted / unclamped; farPlane may be +infinity.
    double nearPlane = 0.0;
    double farPlane = 0.0;
    bool reversedZ = false;
    float polygonOffsetClamp = 0.0f;
    int cascades = kAutoCascades;
    double cascadeLambda = 0.75;
    double cascadeBlend = 0.0;
    bool stable = true;
    bool cullUnseenCasters = true;  // leave out casters whose shadow no visible receiver can show
    Projection projection = Projection::Uniform;  // directional lights' single map
    double lispsmNScale = 1.0;  // n = lispsmNScale * n_opt (math/LispsmWarp.h)
    double casterLod = 0.0;     // texels; 0: every caster drawn as loaded
    double shadowDistance = 0.0;  // directional lights, world units; 0: no limit
    double shadowFade = 0.1;      // fraction of shadowDistance
    // The light's size (see the table above): what the area truth samples and what a
    // soft filter spreads the shadow by. Each applies to its light types only.
    double lightRadius = 0.0;      // spot and point lights, world units
    double angularDiameter = 0.0;  // directional lights, radians

    // The size that applies to a light of `type`: its radius, or its angular diameter.
    double lightSize(engine::Light::Type type) const {
        return type == engine::Light::Type::Directional ? angularDiameter : lightRadius;
    }

    bool operator==(const ShadowSettings&) const = default;
};

// ---- Reading -----------------------------------------------------------------------------
// Every bad value throws engine::InputError "source: object.key: reason", e.g.
// "scene.gltf: light \"sun\": extras.shadow.dimming: must be in [0, 1], got 1.5".

// Applies the keys of `json` (an object) over `settings`. `source` and `object` name where
// the JSON came from for messages, e.g. ("scene.gltf", "light \"sun\": extras.shadow").
void applySettings(ShadowSettings& settings, const nlohmann::json& json, const std::string& source,
                   const std::string& object);
// applySettings over the built-in defaults: parseSettings(printSettings(s), ...) == s.
ShadowSettings parseSettings(const nlohmann::json& json, const std::string& source, const std::string& object);

Variant parseVariant(const std::string& text, const std::string& source, const std::string& object);

// The taps filter_taps accepts.
inline constexpr int kMinFilterTaps = 4, kMaxFilterTaps = 64;
// The widest filter_radius, in texels: wider kernels cost taps and blur contact shadows
// away; a light with a size wants pcss instead.
inline constexpr double kMaxFilterRadius = 16.0;
// The largest bleed_reduction: at 1 the bound would be cut off whole (every penumbra a
// hard step, and 0/0 in the stretch).
inline constexpr double kMaxBleedReduction = 0.95;
// The largest normal_offset, in texels: beyond it a thin caster's shadow detaches visibly.
inline constexpr double kMaxNormalOffset = 8.0;

// Checks what depends on the GL implementation (the resolution limit) and on keys combined
// from several sources (reversed_z needs d32f; near_plane < far_plane).
void checkLimits(const ShadowSettings& settings, int maxTextureSize, const std::string& source,
                 const std::string& object);

// A light's own settings JSON (extras.shadow, the command line's) may only size it the way
// its type is sized: light_radius on a directional light, or angular_diameter on a spot or
// point light, throws InputError "source: object.key: reason".
void checkSizeKeyForType(const nlohmann::json& json, engine::Light::Type type, const std::string& source,
                         const std::string& object);
// A soft filter (pcss) needs the light to have a size: without one it would be a hard shadow
// no one asked for. InputError "source: object.filter: reason" naming the key to set.
// filter_radius widens pcf only: with another filter it is "source: object.filter_radius".
void checkFilterForType(const ShadowSettings& settings, engine::Light::Type type, const std::string& source,
                        const std::string& object);
// A light's own settings JSON may ask for projection "lispsm" only on a directional light:
// InputError "source: object.projection: reason" otherwise.
void checkProjectionKeyForType(const nlohmann::json& json, engine::Light::Type type, const std::string& source,
                               const std::string& object);

// ---- Writing -----------------------------------------------------------------------------

// The settings as an extras.shadow object that parseSettings() reads back to equal
// settings: every key that holds a value (variant, resolution, depth_format, filter,
// dimming, reversed_z, polygon_offset_clamp always; polygon_offset when explicit;
// near_plane and far_plane when forced, far_plane "infinite" for an infinite one). A key
// left out means "the default", which for those three is not a number: the variant's
// offset, the fitted plane.
nlohmann::json printSettings(const ShadowSettings& settings);

// A float setting as the decimal it was written as: float 0.4 widened to double would read
// 0.4000000059604645; its shortest float decimal reads 0.4 and parses back to the same float.
double jsonNumber(float value);

// ---- Allowed values per key --------------------------------------------------------------

enum class SettingKind {
    Choice,      // a string among `choices`
    Integer,     // a whole number in [minimum, maximum]; `choices` lists words accepted
                 // instead of a number ("auto")
    Number,      // a finite number; `minimum`/`maximum` bound it where set; `choices` lists
                 // words accepted instead of a number ("infinite")
    NumberPair,  // [a, b] of finite numbers
    Boolean,     // true or false
};

// One key of extras.shadow (and of the plugin's config settings), for tools and docs.
struct SettingKey {
    std::string name;                   // as in JSON: "depth_format"
    SettingKind kind = SettingKind::Choice;
    std::vector<std::string> choices;   // every accepted string, in declaration order
    std::optional<double> minimum;      // inclusive bounds (exclusive ones are in `values`)
    std::optional<double> maximum;
    std::vector<double> steps;          // Integer: the values worth stepping through
    std::string values;                 // what it accepts, as people read it
    nlohmann::json defaultValue;        // printSettings(ShadowSettings{})[name]; null: none
    std::string defaultNote;            // the default in words when it is no single value
    std::string description;            // one line
};

// Every key applySettings() accepts, in the order the error messages list them.
const std::vector<SettingKey>& settingKeys();
// The key of that name; std::logic_error for a name that is no key (a caller's bug).
const SettingKey& settingKey(std::string_view name);

// ---- The plugin's config settings --------------------------------------------------------
// The "settings" of the plugin's entry in the engine config: the per-light keys above (the
// defaults every light's extras.shadow overrides) and these plugin-wide ones.

// "cache_maps": true (default) keeps a light's map across frames while nothing it depends
// on changed, and lets the lit pass reuse its shade; false re-renders every map and
// recomputes every shade every frame (for timing the passes). --stats reports it by this key.
inline constexpr char kCacheMapsKey[] = "cache_maps";
// "volume_extrusion": where variant volume's shadow volumes are made: "cpu" (default) from each
// mesh's edge adjacency on the CPU, or "gpu" in a geometry shader for closed meshes (the others,
// and skinned or morphed casters, stay on the CPU). docs/shadow-volumes.md measures both.
inline constexpr char kVolumeExtrusionKey[] = "volume_extrusion";
// "volume_counting": how variant volume counts a caster's volume: "auto" (default) with z-pass,
// without caps, where the volume cannot hold the camera (the CPU's closed casters), else
// z-fail; or "z-fail" for every volume (the same shadows; for measuring what z-pass saves).
inline constexpr char kVolumeCountingKey[] = "volume_counting";

struct PluginSettings {
    ShadowSettings lightDefaults;
    bool cacheMaps = true;
    bool volumesOnGpu = false;  // volume_extrusion "gpu"
    bool volumesZPass = true;   // volume_counting "auto"

    bool operator==(const PluginSettings&) const = default;
};

// The plugin's config settings over the built-in defaults. Every bad value, and any key not
// in pluginSettingKeys(), throws engine::InputError "source: settings.key: reason".
PluginSettings parsePluginSettings(const nlohmann::json& json, const std::string& source);

// Every key the plugin's config settings accept: settingKeys()' names, then cache_maps and
// volume_extrusion.
std::vector<std::string> pluginSettingKeys();

} // namespace shadowmap
