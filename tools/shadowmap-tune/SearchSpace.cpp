#include "SearchSpace.h"

#include "shadowmap/ShadowSettings.h"

#include <cstdio>

namespace shadowmap_tune {

std::vector<SettingDimension> searchSpace(const SearchLimits& limits) {
    const auto values = [](const auto& list) {
        std::vector<nlohmann::json> out;
        for (const auto& item : list) out.emplace_back(item);
        return out;
    };
    // The order is the report's: "standard 1024 d24 pcf".
    return {
        {"variant", values(limits.variants), false},
        {"resolution", values(limits.resolutions), true},
        {"depth_format", values(limits.depthFormats), false},
        {"filter", values(limits.filters), false},
    };
}

std::vector<std::string> ownedKeys(const std::vector<SettingDimension>& space) {
    std::vector<std::string> keys;
    for (const SettingDimension& dimension : space) keys.push_back(dimension.key);
    keys.push_back("polygon_offset");
    return keys;
}

std::vector<Candidate> coarseCandidates(const std::vector<SettingDimension>& space) {
    std::vector<Candidate> candidates = {Candidate::object()};
    for (const SettingDimension& dimension : space) {
        if (dimension.values.empty()) continue;
        std::vector<Candidate> next;
        for (const Candidate& partial : candidates) {
            if (dimension.refined) {
                Candidate one = partial;
                one[dimension.key] = dimension.values.front();
                next.push_back(std::move(one));
                continue;
            }
            for (const nlohmann::json& value : dimension.values) {
                Candidate one = partial;
                one[dimension.key] = value;
                next.push_back(std::move(one));
            }
        }
        candidates = std::move(next);
    }
    return candidates;
}

std::vector<Candidate> refinedCandidates(const std::vector<SettingDimension>& space, const Candidate& kept) {
    std::vector<Candidate> candidates;
    for (const SettingDimension& dimension : space) {
        if (!dimension.refined) continue;
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
        text += (text.empty() ? "" : " ") + (value.is_string() ? value.get<std::string>() : value.dump());
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
    return text;
}

bool usesPolygonOffset(const Candidate& candidate) {
    shadowmap::ShadowSettings settings;
    if (candidate.contains("variant") && candidate["variant"].is_string())
        settings.variant = shadowmap::parseVariant(candidate["variant"], "shadowmap-tune", "candidate");
    const glm::vec2 offset = shadowmap::defaultPolygonOffset(settings.variant, shadowmap::Filter::Pcf, false);
    return offset.x != 0.0f || offset.y != 0.0f;
}

std::array<long, 3> expectedCost(const Candidate& candidate) {
    const shadowmap::ShadowSettings settings = shadowmap::parseSettings(candidate, "shadowmap-tune", "candidate");
    const long passes = settings.variant == shadowmap::Variant::Woo ? 2 : 1;
    const long texels = static_cast<long>(settings.resolution) * settings.resolution * passes * settings.cascades;
    const long taps = settings.filter == shadowmap::Filter::Pcf ? 4 : 1;
    const long bytes = settings.depthFormat == shadowmap::DepthFormat::D16 ? 2 : settings.depthFormat == shadowmap::DepthFormat::D24 ? 3 : 4;
    return {texels, taps, bytes};
}

long gridSize(const std::vector<SettingDimension>& space, long offsetLatticeSize) {
    long withOffset = 1, withoutOffset = 1;
    for (const SettingDimension& dimension : space) {
        if (dimension.values.empty()) continue;
        if (dimension.key == "variant") {
            long offsetVariants = 0;
            for (const nlohmann::json& value : dimension.values)
                offsetVariants += usesPolygonOffset({{"variant", value}});
            withOffset *= offsetVariants;
            withoutOffset *= static_cast<long>(dimension.values.size()) - offsetVariants;
        } else {
            withOffset *= static_cast<long>(dimension.values.size());
            withoutOffset *= static_cast<long>(dimension.values.size());
        }
    }
    return withOffset * offsetLatticeSize + withoutOffset;
}

} // namespace shadowmap_tune
