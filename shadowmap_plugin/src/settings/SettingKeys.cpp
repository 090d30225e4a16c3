// The allowed-values table (shadowmap/ShadowSettings.h): what each key accepts, its
// default and what it means. Choices come from the enums' JSON names and defaults from
// printSettings(ShadowSettings{}), so the table cannot disagree with parsing or defaults.
#include "shadowmap/ShadowSettings.h"

#include "settings/EnumNames.h"

#include "engine/util/FormatNumber.h"

#include <stdexcept>

namespace shadowmap {

namespace {

template <std::size_t N>
std::vector<std::string> choicesOf(const char* const (&names)[N]) {
    return std::vector<std::string>(std::begin(names), std::end(names));
}

std::string pair(glm::vec2 value) {
    std::string text = "[";
    text += engine::formatNumber(value.x) + ", " + engine::formatNumber(value.y) + "]";
    return text;
}

// The standard variant's default offsets in words, from defaultPolygonOffset() itself.
std::string defaultOffsetNote() {
    const glm::vec2 nearest = defaultPolygonOffset(Variant::Standard, Filter::Nearest, false);
    const glm::vec2 pcf = defaultPolygonOffset(Variant::Standard, Filter::Pcf, false);
    const glm::vec2 reversed = defaultPolygonOffset(Variant::Standard, Filter::Pcf, true);
    std::string note = "standard: ";
    note += pair(nearest) + " " + toString(Filter::Nearest) + ", " + pair(pcf) + " " + toString(Filter::Pcf) + " and " +
            toString(Filter::Pcss);
    note += ", units " + engine::formatNumber(reversed.y) + " with reversed_z; ";
    note += std::string(toString(Variant::Woo)) + ", " + toString(Variant::Backface) + ": none";
    return note;
}

SettingKey makeKey(const char* name, SettingKind kind) {
    SettingKey key;
    key.name = name;
    key.kind = kind;
    return key;
}

std::vector<SettingKey> makeKeys() {
    std::vector<SettingKey> keys;

    SettingKey variant = makeKey("variant", SettingKind::Choice);
    variant.choices = choicesOf(names::kVariants);
    variant.description = "how the light's map is made: `standard` one depth pass with polygon offset, "
                          "`woo` the midpoint of the first two layers, `backface` back faces only "
                          "(closed meshes), `none` no shadow and no pass, `volume` no map: stenciled shadow "
                          "volumes, exact hard shadows per camera pixel";
    keys.push_back(variant);

    SettingKey resolution = makeKey("resolution", SettingKind::Integer);
    resolution.minimum = 1;
    resolution.maximum = 1 << 20;  // beyond any GL; the GL's own GL_MAX_TEXTURE_SIZE is checked too
    resolution.steps = {512, 1024, 2048, 4096};
    resolution.values = "1 … GL_MAX_TEXTURE_SIZE";
    resolution.description = "texels per side of the map (of each cube face for a point light)";
    keys.push_back(resolution);

    SettingKey format = makeKey("depth_format", SettingKind::Choice);
    format.choices = choicesOf(names::kDepthFormats);
    format.description = "the map's depth: 16- or 24-bit fixed point, or 32-bit float";
    keys.push_back(format);

    SettingKey filter = makeKey("filter", SettingKind::Choice);
    filter.choices = choicesOf(names::kFilters);
    filter.description = "`nearest` one tap, `pcf` 2×2 bilinear percentage-closer filtering, `pcss` "
                         "percentage-closer soft shadows: a penumbra as wide as the light's size makes it "
                         "(needs `light_radius` or `angular_diameter`), `vsm` and `evsm` filterable maps of depth "
                         "moments, blurred by `filter_radius` and read with one filtered fetch (light may bleed where "
                         "occluders overlap)";
    keys.push_back(filter);

    SettingKey taps = makeKey("filter_taps", SettingKind::Integer);
    taps.minimum = kMinFilterTaps;
    taps.maximum = kMaxFilterTaps;
    taps.steps = {8, 16, 32, 64};
    taps.values = std::to_string(kMinFilterTaps) + " … " + std::to_string(kMaxFilterTaps);
    taps.description = "`pcss` and wide `pcf`: the filter's taps, each a 2×2 bilinear comparison; pcss's blocker "
                       "search takes half as many";
    keys.push_back(taps);

    SettingKey filterRadius = makeKey("filter_radius", SettingKind::Number);
    filterRadius.minimum = 0;
    filterRadius.maximum = kMaxFilterRadius;
    filterRadius.values = "0 … " + engine::formatNumber(kMaxFilterRadius) + ", texels";
    filterRadius.description = "`pcf`: filter over a disk of this radius (`filter_taps` rotated taps) instead of "
                               "one 2×2 tap; 0: the one tap. `vsm`, `evsm`: the moments' box blur, this many texels "
                               "each side";
    keys.push_back(filterRadius);

    SettingKey bleed = makeKey("bleed_reduction", SettingKind::Number);
    bleed.minimum = 0;
    bleed.maximum = kMaxBleedReduction;
    bleed.values = "0 … " + engine::formatNumber(kMaxBleedReduction);
    bleed.description = "`vsm`, `evsm`: the share of Chebyshev's bound cut off as light bleeding where occluders "
                        "overlap (the rest stretched over 0 … 1); higher darkens penumbrae too";
    keys.push_back(bleed);

    SettingKey exponents = makeKey("evsm_exponents", SettingKind::NumberPair);
    exponents.values = "`[positive, negative]`, each in (0, " + engine::formatNumber(kMaxEvsmExponent) + "]";
    exponents.description = "`evsm`: the exponents of its depth warps; larger bleeds less, and 32-bit moments "
                            "overflow beyond " + engine::formatNumber(kMaxEvsmExponent);
    keys.push_back(exponents);

    SettingKey mipmaps = makeKey("moments_mipmaps", SettingKind::Boolean);
    mipmaps.values = "`true`, `false`";
    mipmaps.description = "`vsm`, `evsm`: mipmap a 2D map's moments (spot, one directional map) and read them "
                          "trilinearly and anisotropically; cascades and cube maps read their first level";
    keys.push_back(mipmaps);

    SettingKey normalOffset = makeKey("normal_offset", SettingKind::Number);
    normalOffset.minimum = 0;
    normalOffset.maximum = kMaxNormalOffset;
    normalOffset.values = "0 … " + engine::formatNumber(kMaxNormalOffset) + ", texels";
    normalOffset.description = "the lookup moves the receiver along its normal by this many texels of the map "
                               "there, times the sine of the light's angle to the normal: acne at grazing light "
                               "goes, at the price of shadows that start a little late";
    keys.push_back(normalOffset);

    SettingKey offset = makeKey("polygon_offset", SettingKind::NumberPair);
    offset.values = "`[factor, units]`";
    offset.defaultNote = defaultOffsetNote();
    offset.description = "glPolygonOffset of the depth pass (woo: of both its passes), in texels of "
                         "slope and steps of the depth format";
    keys.push_back(offset);

    SettingKey dimming = makeKey("dimming", SettingKind::Number);
    dimming.minimum = 0;
    dimming.maximum = 1;
    dimming.values = "0 … 1";
    dimming.description = "the share of its diffuse light a shadowed surface keeps";
    keys.push_back(dimming);

    SettingKey nearPlane = makeKey("near_plane", SettingKind::Number);
    nearPlane.values = "> 0, world units";
    nearPlane.defaultNote = "fitted";
    nearPlane.description = "the near distance of a spot or point light's frustum instead of the fitted "
                            "one (directional lights ignore it)";
    keys.push_back(nearPlane);

    SettingKey farPlane = makeKey("far_plane", SettingKind::Number);
    farPlane.choices = {"infinite"};
    farPlane.values = "> near_plane, world units, or `infinite`";
    farPlane.defaultNote = "fitted; with reversed_z: infinite";
    farPlane.description = "the far distance instead of the fitted one (spot and point lights)";
    keys.push_back(farPlane);

    SettingKey reversedZ = makeKey("reversed_z", SettingKind::Boolean);
    reversedZ.values = "`true`, `false`";
    reversedZ.description = "depth 1 at near and 0 at far (glClipControl), float precision at any range; "
                            "needs depth_format `d32f`";
    keys.push_back(reversedZ);

    SettingKey clamp = makeKey("polygon_offset_clamp", SettingKind::Number);
    clamp.minimum = 0;
    clamp.values = "≥ 0, a slope";
    clamp.description = "the slope at which the offset's slope-scaled part stops growing "
                        "(glPolygonOffsetClamp); 0: unclamped";
    keys.push_back(clamp);

    SettingKey cascades = makeKey("cascades", SettingKind::Integer);
    cascades.minimum = 1;
    cascades.maximum = kMaxCascades;
    for (int count = 1; count <= kMaxCascades; ++count) cascades.steps.push_back(count);
    cascades.choices = {"auto"};
    cascades.values = "`auto`, 1 … " + std::to_string(kMaxCascades);
    cascades.description = "directional lights: slices of the camera's view depth, each with its own map "
                           "(a layer of the light's array map); 1: one map for every visible receiver; "
                           "`auto`: the count the view needs, chosen per frame";
    keys.push_back(cascades);

    SettingKey lambda = makeKey("cascade_lambda", SettingKind::Number);
    lambda.minimum = 0;
    lambda.maximum = 1;
    lambda.values = "0 … 1";
    lambda.description = "the split scheme's weight of logarithmic (1) over uniform (0) split distances";
    keys.push_back(lambda);

    SettingKey blend = makeKey("cascade_blend", SettingKind::Number);
    blend.minimum = 0;
    blend.maximum = 0.5;
    blend.values = "0 … 0.5";
    blend.description = "the band past each split, as a fraction of the nearer cascade's depth range, over which "
                        "the lookup fades into the next cascade; 0: a hard switch";
    keys.push_back(blend);

    SettingKey stable = makeKey("stable", SettingKind::Boolean);
    stable.values = "`true`, `false`";
    stable.description = "cascades snapped to whole texels in squares of fixed size, so shadows do not "
                         "crawl while the camera moves";
    keys.push_back(stable);

    SettingKey distance = makeKey("shadow_distance", SettingKind::Number);
    distance.minimum = 0;
    distance.values = "≥ 0, world units";
    distance.description = "directional lights: the view depth where shadows end; the maps cover no farther, so "
                           "their texels shrink with it; 0: every visible receiver";
    keys.push_back(distance);

    SettingKey fade = makeKey("shadow_fade", SettingKind::Number);
    fade.minimum = 0;
    fade.maximum = 1;
    fade.values = "0 … 1";
    fade.description = "directional lights: the last fraction of shadow_distance over which shadows fade out";
    keys.push_back(fade);

    SettingKey radius = makeKey("light_radius", SettingKind::Number);
    radius.minimum = 0;
    radius.values = "≥ 0, world units";
    radius.description = "spot and point lights: the radius of the disk that emits the light (0: a point); "
                         "the area truth samples it";
    keys.push_back(radius);

    SettingKey angular = makeKey("angular_diameter", SettingKind::Number);
    angular.minimum = 0;
    angular.values = "≥ 0, radians";
    angular.description = "directional lights: the apex angle of the cone the light comes from (the sun: "
                          "about 0.0093; 0: one direction); the area truth samples it";
    keys.push_back(angular);

    SettingKey unseen = makeKey("cull_unseen_casters", SettingKind::Boolean);
    unseen.values = "`true`, `false`";
    unseen.description = "leave out of the depth passes the casters whose shadow can fall on no receiver the camera "
                         "sees (the same image; a map drawn without one is drawn again when the view needs it); "
                         "`woo` keeps every caster";
    keys.push_back(unseen);

    SettingKey projection = makeKey("projection", SettingKind::Choice);
    projection.choices = choicesOf(names::kProjections);
    projection.description = "directional lights: `uniform` orthographic maps, `lispsm` light-space perspective "
                             "warps that crowd texels near the camera, of the map or of each cascade (fitted, not "
                             "`stable`: a warp follows the camera; cascades `auto` keeps one map); hard filters only";
    keys.push_back(projection);

    SettingKey nScale = makeKey("lispsm_n_scale", SettingKind::Number);
    nScale.values = "> 0";
    nScale.description = "`lispsm`: multiplies the warp's optimal near distance n; above 1 the warp weakens toward "
                         "uniform, below 1 it magnifies the near end more";
    keys.push_back(nScale);

    SettingKey lod = makeKey("caster_lod", SettingKind::Number);
    lod.minimum = 0;
    lod.values = "≥ 0, texels";
    lod.description = "draw each caster's coarsest simplified level whose geometric error is below this fraction of "
                      "the light's texel at the caster (closed meshes keep closed levels; "
                      "[caster LOD](docs/caster-lod.md)); 0: every caster as loaded";
    keys.push_back(lod);

    const nlohmann::json defaults = printSettings(ShadowSettings{});
    for (SettingKey& key : keys) {
        if (defaults.contains(key.name)) key.defaultValue = defaults[key.name];
        if (key.kind == SettingKind::Choice) {
            key.values.clear();
            for (const std::string& choice : key.choices) {
                key.values += key.values.empty() ? "`" : ", `";
                key.values += choice + "`";
            }
        }
    }
    return keys;
}

} // namespace

const std::vector<SettingKey>& settingKeys() {
    static const std::vector<SettingKey> keys = makeKeys();
    return keys;
}

const SettingKey& settingKey(std::string_view name) {
    for (const SettingKey& key : settingKeys())
        if (key.name == name) return key;
    throw std::logic_error("no shadow setting \"" + std::string(name) + "\"");
}

} // namespace shadowmap
