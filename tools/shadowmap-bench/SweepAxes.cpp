#include "SweepAxes.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <functional>

namespace shadowmap_bench {

namespace {

using Expansion = std::function<std::vector<ShadowSetting>(const ShadowSetting&)>;

std::vector<ShadowSetting> expand(const std::vector<ShadowSetting>& settings, const Expansion& each) {
    std::vector<ShadowSetting> out;
    for (const ShadowSetting& setting : settings) {
        const std::vector<ShadowSetting> expanded = each(setting);
        out.insert(out.end(), expanded.begin(), expanded.end());
    }
    return out;
}

// `setting` once per value of `values` in `field`; as it is when the axis does not apply
// or was not given.
template <typename T>
std::vector<ShadowSetting> perValue(const ShadowSetting& setting, const std::vector<T>& values,
                                    std::optional<T> ShadowSetting::*field, bool applies) {
    if (!applies || values.empty()) return {setting};
    std::vector<ShadowSetting> out;
    for (const T& value : values) {
        out.push_back(setting);
        out.back().*field = value;
    }
    return out;
}

// The k-th step takes the k-th radius and the k-th diameter; a list not given leaves that
// type of light its own size.
std::vector<ShadowSetting> perSizeStep(const ShadowSetting& setting, const BenchOptions& options) {
    const std::size_t steps = std::max(options.lightRadii.size(), options.angularDiameters.size());
    if (steps == 0) return {setting};
    std::vector<ShadowSetting> out(steps, setting);
    for (std::size_t k = 0; k < steps; ++k) {
        if (!options.lightRadii.empty()) out[k].lightRadius = options.lightRadii[k];
        if (!options.angularDiameters.empty()) out[k].angularDiameter = options.angularDiameters[k];
    }
    return out;
}

bool isFilter(const ShadowSetting& setting, shadowmap::Filter filter) {
    return setting.filter == shadowmap::toString(filter);
}

// The filters that read depth moments (vsm, evsm): filter_radius blurs their moments, and
// bleed_reduction cuts their light bleeding.
bool readsMoments(const ShadowSetting& setting) {
    return isFilter(setting, shadowmap::Filter::Vsm) || isFilter(setting, shadowmap::Filter::Evsm);
}

// The filters that read filter_radius: pcf's disk, vsm's and evsm's blur.
bool takesFilterRadius(const ShadowSetting& setting) {
    return isFilter(setting, shadowmap::Filter::Pcf) || readsMoments(setting);
}

// The filters that read filter_taps: pcss, and pcf widened by a filter radius.
bool takesTaps(const ShadowSetting& setting) {
    return isFilter(setting, shadowmap::Filter::Pcss) ||
           (isFilter(setting, shadowmap::Filter::Pcf) && setting.filterRadius.value_or(0.0) > 0.0);
}

bool isLispsm(const ShadowSetting& setting) {
    return setting.projection == shadowmap::Projection::Lispsm;
}

// The setting without its directional-only fields: what a spot or point light gets of it.
ShadowSetting withoutDirectionalAxes(ShadowSetting setting) {
    setting.projection = std::nullopt;
    setting.cascades = std::nullopt;
    setting.stable = std::nullopt;
    setting.directionalRepeat = false;
    return setting;
}

} // namespace

std::vector<ShadowSetting> expandAxes(const std::vector<ShadowSetting>& settings, const BenchOptions& options) {
    std::vector<ShadowSetting> out =
        expand(settings, [&](const ShadowSetting& setting) { return perSizeStep(setting, options); });
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.filterRadii, &ShadowSetting::filterRadius, takesFilterRadius(setting));
    });
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.filterTaps, &ShadowSetting::filterTaps, takesTaps(setting));
    });
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.bleedReductions, &ShadowSetting::bleedReduction, readsMoments(setting));
    });
    // A volume light has no map to offset, project or slice: of the axes it takes only the
    // light size steps (its truth changes with them).
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.normalOffsets, &ShadowSetting::normalOffset, rendersMap(setting.variant));
    });
    // The directional lights' axes last, so that the settings a spot or point light cannot
    // tell apart stand next to each other.
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.projections, &ShadowSetting::projection, rendersMap(setting.variant));
    });
    out = expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.cascades, &ShadowSetting::cascades, rendersMap(setting.variant));
    });
    return expand(out, [&](const ShadowSetting& setting) {
        return perValue(setting, options.stables, &ShadowSetting::stable,
                        rendersMap(setting.variant) && !isLispsm(setting));
    });
}

void markDirectionalRepeats(std::vector<ShadowSetting>& settings) {
    for (std::size_t k = 0; k < settings.size(); ++k) {
        const ShadowSetting plain = withoutDirectionalAxes(settings[k]);
        settings[k].directionalRepeat =
            std::any_of(settings.begin(), settings.begin() + k,
                        [&](const ShadowSetting& earlier) { return withoutDirectionalAxes(earlier) == plain; });
    }
}

bool writesRowFor(const ShadowSetting& setting, engine::Light::Type type) {
    return type == engine::Light::Type::Directional || !setting.directionalRepeat;
}

ShadowSetting rowSetting(const ShadowSetting& setting, engine::Light::Type type) {
    return type == engine::Light::Type::Directional ? setting : withoutDirectionalAxes(setting);
}

nlohmann::json lightShadow(const ShadowSetting& setting, engine::Light::Type type) {
    nlohmann::json shadow = {{"variant", setting.variant}};
    if (rendersMap(setting.variant)) {
        shadow["resolution"] = setting.resolution;
        shadow["depth_format"] = setting.depthFormat;
        shadow["filter"] = setting.filter;
    }
    const bool directional = type == engine::Light::Type::Directional;
    const auto write = [&](const char* key, const auto& value) {
        if (value) shadow[key] = *value;
    };
    write(directional ? "angular_diameter" : "light_radius", directional ? setting.angularDiameter : setting.lightRadius);
    write("filter_radius", setting.filterRadius);
    write("filter_taps", setting.filterTaps);
    write("bleed_reduction", setting.bleedReduction);
    write("normal_offset", setting.normalOffset);
    if (directional) {
        if (setting.projection) shadow["projection"] = shadowmap::toString(*setting.projection);
        if (setting.cascades) {
            if (*setting.cascades == shadowmap::kAutoCascades) shadow["cascades"] = "auto";
            else shadow["cascades"] = *setting.cascades;
        }
        write("stable", setting.stable);
    }
    return shadow;
}

} // namespace shadowmap_bench
