// Settings back to JSON (shadowmap/ShadowSettings.h), in the form applySettings() reads.
#include "shadowmap/ShadowSettings.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace shadowmap {

double jsonNumber(float value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::strtod(std::string(text, end).c_str(), nullptr);
}

nlohmann::json printSettings(const ShadowSettings& settings) {
    nlohmann::json out = {{"variant", toString(settings.variant)},
                          {"resolution", settings.resolution},
                          {"depth_format", toString(settings.depthFormat)},
                          {"filter", toString(settings.filter)},
                          {"filter_taps", settings.filterTaps},
                          {"filter_radius", settings.filterRadius},
                          {"normal_offset", settings.normalOffset},
                          {"bleed_reduction", settings.bleedReduction},
                          {"evsm_exponents", {jsonNumber(settings.evsmExponents.x), jsonNumber(settings.evsmExponents.y)}},
                          {"moments_mipmaps", settings.momentsMipmaps},
                          {"dimming", jsonNumber(settings.dimming)},
                          {"reversed_z", settings.reversedZ},
                          {"polygon_offset_clamp", jsonNumber(settings.polygonOffsetClamp)},
                          {"cascades", settings.cascades == kAutoCascades ? nlohmann::json("auto")
                                                                          : nlohmann::json(settings.cascades)},
                          {"cascade_lambda", settings.cascadeLambda},
                          {"cascade_blend", settings.cascadeBlend},
                          {"stable", settings.stable},
                          {"cull_unseen_casters", settings.cullUnseenCasters},
                          {"projection", toString(settings.projection)},
                          {"lispsm_n_scale", settings.lispsmNScale},
                          {"caster_lod", settings.casterLod},
                          {"shadow_distance", settings.shadowDistance},
                          {"shadow_fade", settings.shadowFade},
                          {"light_radius", settings.lightRadius},
                          {"angular_diameter", settings.angularDiameter}};
    if (settings.polygonOffset)
        out["polygon_offset"] = {jsonNumber(settings.polygonOffset->x), jsonNumber(settings.polygonOffset->y)};
    // 0 stands for "fitted", which applySettings() does not accept as a distance.
    if (settings.nearPlane > 0.0) out["near_plane"] = settings.nearPlane;
    if (settings.farPlane > 0.0) {
        if (std::isinf(settings.farPlane)) out["far_plane"] = "infinite";  // JSON has no infinity
        else out["far_plane"] = settings.farPlane;
    }
    return out;
}

} // namespace shadowmap
