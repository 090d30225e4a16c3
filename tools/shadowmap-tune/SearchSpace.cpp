#include "SearchSpace.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <cstdio>

namespace shadowmap_tune {

namespace {

// The product of the dimensions, each where it applies: every value, or only the first of
// a refined dimension unless `allValues`.
std::vector<Candidate> product(const std::vector<SettingDimension>& space, bool allValues) {
    std::vector<Candidate> candidates = {Candidate::object()};
    for (const SettingDimension& dimension : space) {
        if (dimension.values.empty()) continue;
        std::vector<Candidate> next;
        for (const Candidate& partial : candidates) {
            if (!dimension.appliesTo(partial)) {
                next.push_back(partial);
                continue;
            }
            const std::size_t count = dimension.refined && !allValues ? 1 : dimension.values.size();
            for (std::size_t i = 0; i < count; ++i) {
                Candidate one = partial;
                one[dimension.key] = dimension.values[i];
                next.push_back(std::move(one));
            }
        }
        candidates = std::move(next);
    }
    return candidates;
}

} // namespace

bool SettingDimension::appliesTo(const Candidate& candidate) const {
    const auto& [key, value] = onlyWith;
    const auto& [excludingKey, excludingValue] = notWith;
    if (!excludingKey.empty() && candidate.contains(excludingKey) && candidate[excludingKey] == excludingValue)
        return false;
    return key.empty() || (candidate.contains(key) && candidate[key] == value);
}

std::vector<SettingDimension> searchSpace(const SearchLimits& limits) {
    const auto values = [](const auto& list) {
        std::vector<nlohmann::json> out;
        for (const auto& item : list) out.emplace_back(item);
        return out;
    };
    // The order is the report's: "standard 1024 d24 pcss taps16". filter_taps comes after
    // the filter it depends on, and is refined: more taps smooth a penumbra more, so the
    // fewest ranks pcss against the other filters. A volume light has no map: one
    // candidate, "volume", rather than the same picture once per resolution, format and
    // filter (with a soft filter the plugin would also warn that it ignores it).
    const std::pair<std::string, nlohmann::json> noMap{"variant", shadowmap::toString(shadowmap::Variant::Volume)};
    return {
        {"variant", values(limits.variants), false, "", {}, {}},
        {"resolution", values(limits.resolutions), true, "", {}, noMap},
        {"depth_format", values(limits.depthFormats), false, "", {}, noMap},
        {"filter", values(limits.filters), false, "", {}, noMap},
        {"filter_taps", values(limits.filterTaps), true, "taps", {"filter", shadowmap::toString(shadowmap::Filter::Pcss)},
         {}},
    };
}

std::vector<std::string> ownedKeys(const std::vector<SettingDimension>& space) {
    std::vector<std::string> keys;
    for (const SettingDimension& dimension : space)
        if (dimension.onlyWith.first.empty()) keys.push_back(dimension.key);
    keys.push_back("polygon_offset");
    return keys;
}

Candidate candidateOf(const std::vector<SettingDimension>& space, const nlohmann::json& used) {
    Candidate candidate = Candidate::object();
    for (const SettingDimension& dimension : space)
        if (used.contains(dimension.key) && dimension.appliesTo(candidate)) candidate[dimension.key] = used[dimension.key];
    return candidate;
}

std::vector<Candidate> coarseCandidates(const std::vector<SettingDimension>& space) { return product(space, false); }

std::vector<Candidate> fullGrid(const std::vector<SettingDimension>& space) { return product(space, true); }

std::vector<Candidate> refinedCandidates(const std::vector<SettingDimension>& space, const Candidate& kept) {
    std::vector<Candidate> candidates;
    for (const SettingDimension& dimension : space) {
        if (!dimension.refined || !dimension.appliesTo(kept)) continue;
        for (const nlohmann::json& value : dimension.values) {
            if (kept.contains(dimension.key) && kept[dimension.key] == value) continue;
            Candidate one = kept;
            one[dimension.key] = value;
            candidates.push_back(std::move(one));
        }
    }
    return candidates;
}

std::string describe(const Candidate& candidate, const std::vector<SettingDimension>& space) {
    std::string text;
    for (const SettingDimension& dimension : space) {
        if (!candidate.contains(dimension.key)) continue;
        const nlohmann::json& value = candidate[dimension.key];
        text += (text.empty() ? "" : " ") + dimension.prefix + (value.is_string() ? value.get<std::string>() : value.dump());
    }
    if (candidate.contains("polygon_offset") && candidate["polygon_offset"].is_array() &&
        candidate["polygon_offset"].size() == 2) {
        char offset[64];
        std::snprintf(offset, sizeof offset, " offset [%g, %g]", candidate["polygon_offset"][0].get<double>(),
                      candidate["polygon_offset"][1].get<double>());
        text += offset;
    } else if (usesPolygonOffset(candidate)) {
        text += " offset default";
    }
    if (candidate.contains("normal_offset") && candidate["normal_offset"].is_number()) {
        char offset[64];
        std::snprintf(offset, sizeof offset, " normal %g", candidate["normal_offset"].get<double>());
        text += offset;
    }
    return text;
}

bool usesPolygonOffset(const Candidate& candidate) {
    shadowmap::ShadowSettings settings;
    if (candidate.contains("variant") && candidate["variant"].is_string())
        settings.variant = shadowmap::parseVariant(candidate["variant"], "shadowmap-tune", "candidate");
    const glm::vec2 offset = shadowmap::defaultPolygonOffset(settings.variant, shadowmap::Filter::Pcf, false);
    return offset.x != 0.0f || offset.y != 0.0f;
}

std::array<long, 3> expectedCost(const Candidate& candidate, long imagePixels) {
    const shadowmap::ShadowSettings settings = shadowmap::parseSettings(candidate, "shadowmap-tune", "candidate");
    if (settings.variant == shadowmap::Variant::Volume) {
        // VolumeRenderer: the camera's depth over the view (shared by a frame's volume
        // lights, counted for each), the volumes' front and back faces in the stencil
        // buffer (each covers about the view where shadows fall), and the resolve into the
        // visibility texture: kVolumePixelPasses full-view passes. Then one visibility
        // texel read per pixel, and a 4-byte depth-stencil buffer (D24S8).
        return {imagePixels * kVolumePixelPasses, 1, 4};
    }
    const long passes = settings.variant == shadowmap::Variant::Woo ? 2 : 1;
    // cascades "auto" (kAutoCascades, 0) is the count the view needs, at least one: counted
    // as one, or every auto setting's texels would be 0 and resolution would rank nothing.
    const long cascades = std::max(settings.cascades, 1);
    // vsm and evsm also render the moments from the depth map: one full-map pass, two with
    // a blur (filter_radius > 0: rows, then columns; MomentsPasses.cpp).
    const long momentsPasses =
        shadowmap::readsMoments(settings.filter) ? (settings.filterRadius > 0.0 ? 2 : 1) : 0;
    const long texels = static_cast<long>(settings.resolution) * settings.resolution * (passes + momentsPasses) * cascades;
    // A 2x2 bilinear comparison reads 4 texels, and so does vsm's and evsm's one bilinear
    // fetch of the moments (8 trilinear, with moments_mipmaps); pcss's blocker search reads
    // fewer than its filter and grows with it, so it ranks nothing differently and is left out.
    constexpr long kBilinearTexels = 4;
    const bool tapped = settings.filter == shadowmap::Filter::Pcss ||
                        (settings.filter == shadowmap::Filter::Pcf && settings.filterRadius > 0.0);
    const long taps = tapped                                      ? kBilinearTexels * settings.filterTaps
                      : settings.filter == shadowmap::Filter::Pcf ? kBilinearTexels
                      : shadowmap::readsMoments(settings.filter)  ? kBilinearTexels * (settings.momentsMipmaps ? 2 : 1)
                                                                  : 1;
    const long bytes = settings.depthFormat == shadowmap::DepthFormat::D16 ? 2 : settings.depthFormat == shadowmap::DepthFormat::D24 ? 3 : 4;
    return {texels, taps, bytes};
}

long gridSize(const std::vector<SettingDimension>& space, long offsetLatticeSize) {
    long size = 0;
    for (const Candidate& candidate : fullGrid(space)) size += usesPolygonOffset(candidate) ? offsetLatticeSize : 1;
    return size;
}

} // namespace shadowmap_tune
