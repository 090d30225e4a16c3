#include "TuneReport.h"

#include "OffsetFit.h"

#include <cstdio>

namespace shadowmap_tune {

namespace {

std::string format(const char* pattern, double a, double b) {
    char text[128];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

nlohmann::json measuredJson(const Measured& m, const std::vector<SettingDimension>& space) {
    return {{"setting", m.setting}, {"label", describe(m.setting, space)}, {"shadow_ms", m.ms},
            {"acne", m.acne},       {"leak", m.leak},                      {"error", m.error},
            {"error_noedge", m.errorNoEdge}, {"evaluated_pixels", m.evaluated}};
}

} // namespace

std::string reportText(const TuneSummary& summary, const std::vector<SettingDimension>& space) {
    std::string text;
    for (std::size_t i = 0; i < summary.choices.size(); ++i) {
        const LightChoice& choice = summary.choices[i];
        text += "light \"" + summary.names[i] + "\": " + describe(choice.before.setting, space) + " -> " +
                (choice.changed ? describe(choice.chosen.setting, space) : "unchanged") + "\n";
        text += format("  shadow time %.2f -> %.2f ms", choice.before.ms, choice.chosen.ms) +
                format(", error %.3f%% -> %.3f%%", choice.before.error, choice.chosen.error) +
                format(" (acne %.3f%% -> %.3f%%", choice.before.acne, choice.chosen.acne) +
                format(", leak %.3f%% -> %.3f%%)\n", choice.before.leak, choice.chosen.leak);
        if (const auto& fit = choice.offsetFit) {
            const auto offset = defaultOffset(fit->base);
            const nlohmann::json& fitted = fit->fitted.setting["polygon_offset"];
            text += "  polygon offset of " + describe(fit->base, space) + ": default " +
                    format("[%g, %g]", offset[0], offset[1]) + format(" error %.3f%% (acne %.3f%%", fit->atDefault.error, fit->atDefault.acne) +
                    format(", leak %.3f%%), fitted ", fit->atDefault.leak, 0) +
                    format("[%g, %g]", fitted[0].get<double>(), fitted[1].get<double>()) +
                    format(" error %.3f%% (acne %.3f%%", fit->fitted.error, fit->fitted.acne) +
                    format(", leak %.3f%%)\n", fit->fitted.leak, 0);
        }
    }
    const long grid = summary.gridPerLight;
    char line[512];
    std::snprintf(line, sizeof line,
                  "search: %d renders of %d view(s) for %zu light(s) at once; the full grid is %ld settings per "
                  "light, as many renders (the search took %.1f%% of it)\n",
                  summary.renders, summary.views, summary.choices.size(), grid,
                  grid > 0 ? 100.0 * summary.renders / static_cast<double>(grid) : 0.0);
    text += line;
    return text;
}

nlohmann::json reportJson(const TuneSummary& summary, const std::vector<SettingDimension>& space) {
    nlohmann::json lights = nlohmann::json::array();
    for (std::size_t i = 0; i < summary.choices.size(); ++i) {
        const LightChoice& choice = summary.choices[i];
        nlohmann::json light = {{"light", summary.names[i]},
                                {"before", measuredJson(choice.before, space)},
                                {"after", measuredJson(choice.chosen, space)},
                                {"changed", choice.changed}};
        nlohmann::json measured = nlohmann::json::array();
        if (i < summary.measured.size())
            for (const Measured& m : summary.measured[i]) measured.push_back(measuredJson(m, space));
        light["measured"] = std::move(measured);
        if (const auto& fit = choice.offsetFit) {
            const auto offset = defaultOffset(fit->base);
            light["offset_fit"] = {{"setting", describe(fit->base, space)},
                                   {"default_offset", {offset[0], offset[1]}},
                                   {"default", measuredJson(fit->atDefault, space)},
                                   {"fitted_offset", fit->fitted.setting["polygon_offset"]},
                                   {"fitted", measuredJson(fit->fitted, space)}};
        }
        lights.push_back(std::move(light));
    }
    return {{"goal", summary.goal.kind == Goal::Kind::Budget ? "budget_ms" : "max_error"},
            {"limit", summary.goal.limit},
            {"views", summary.views},
            {"renders", summary.renders},
            {"grid_per_light", summary.gridPerLight},
            {"lights", lights}};
}

} // namespace shadowmap_tune
