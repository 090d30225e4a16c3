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

bool soft(evaluation::RankingTruth truth) { return truth == evaluation::RankingTruth::Soft; }

nlohmann::json measuredJson(const Measured& m, const std::vector<SettingDimension>& space, evaluation::RankingTruth truth) {
    nlohmann::json json = {{"setting", m.setting}, {"label", describe(m.setting, space)}, {"shadow_ms", m.ms},
                           {"acne", m.acne},       {"leak", m.leak},                      {"error", m.error},
                           {"error_noedge", m.errorNoEdge}, {"evaluated_pixels", m.evaluated}};
    if (soft(truth)) {
        json["penumbra_error"] = m.penumbraError;
        json["penumbra_pixels"] = m.evaluatedPenumbra;
    }
    return json;
}

nlohmann::json latticeJson(const OffsetFitResult& fit) {
    return {{"factor", kOffsetFactors}, {"units", kOffsetUnits}, {"normal_offset", fit.normalOffsets}};
}

std::string listed(const std::vector<double>& values) {
    std::string text;
    for (const double value : values) text += (text.empty() ? "" : ", ") + format("%g", value, 0);
    return text;
}

std::string offsetFitText(const OffsetFitResult& fit, const std::vector<SettingDimension>& space) {
    const auto offset = defaultOffset(fit.base);
    const nlohmann::json& fitted = fit.fitted.setting["polygon_offset"];
    return "  offsets of " + describe(fit.base, space) + ": default " + format("[%g, %g]", offset[0], offset[1]) +
           format(" normal %g", fit.defaultNormalOffset, 0) + " error " + format("%.3f%% (acne %.3f%%", fit.atDefault.error, fit.atDefault.acne) +
           format(", leak %.3f%%), fitted ", fit.atDefault.leak, 0) +
           format("[%g, %g]", fitted[0].get<double>(), fitted[1].get<double>()) + format(" normal %g", fit.fitted.setting["normal_offset"].get<double>(), 0) +
           format(" error %.3f%% (acne %.3f%%", fit.fitted.error, fit.fitted.acne) +
           format(", leak %.3f%%); normal offsets tried from ", fit.fitted.leak, 0) + listed(fit.normalOffsets) +
           " texels\n";
}

} // namespace

std::string reportText(const TuneSummary& summary, const std::vector<SettingDimension>& space) {
    std::string text;
    for (std::size_t i = 0; i < summary.choices.size(); ++i) {
        const LightChoice& choice = summary.choices[i];
        const evaluation::RankingTruth truth = summary.truths.at(i);
        // A light that keeps its setting says why: nothing measured beat it at this size.
        text += "light \"" + summary.names[i] + "\": " + describe(choice.before.setting, space) +
                (choice.changed ? " -> " + describe(choice.chosen.setting, space)
                                : " kept: no setting measured beats it at " + std::to_string(summary.width) + "x" +
                                      std::to_string(summary.height)) +
                "\n";
        text += format("  shadow time %.2f -> %.2f ms, ", choice.before.ms, choice.chosen.ms) +
                evaluation::rankedFigure(truth) + format(" %.3f%% -> %.3f%%", choice.before.error, choice.chosen.error) +
                format(" (acne %.3f%% -> %.3f%%", choice.before.acne, choice.chosen.acne) +
                format(", leak %.3f%% -> %.3f%%", choice.before.leak, choice.chosen.leak) +
                (soft(truth) ? format("; penumbra %.3f%% -> %.3f%%", choice.before.penumbraError,
                                      choice.chosen.penumbraError)
                             : "") +
                ")\n";
        if (choice.changed && choice.chosen.error > choice.before.error)
            text += summary.goal.kind == Goal::Kind::Budget
                        ? format("  the file's own setting errs less but takes %.2f ms, over the %g ms budget\n",
                                 choice.before.ms, summary.goal.limit)
                        : format("  faster within --max-error %g%%; the file's own setting (%.3f%%) errs less\n",
                                 summary.goal.limit, choice.before.error);
        if (choice.offsetFit) text += offsetFitText(*choice.offsetFit, space);
    }
    const long grid = summary.gridPerLight;
    char line[512];
    std::snprintf(line, sizeof line,
                  "search: %d renders of %d view(s) at %dx%d for %zu light(s) at once; the full grid is %ld "
                  "settings per light, as many renders (the search took %.1f%% of it)\n",
                  summary.renders, summary.views, summary.width, summary.height, summary.choices.size(), grid,
                  grid > 0 ? 100.0 * summary.renders / static_cast<double>(grid) : 0.0);
    text += line;
    return text;
}

nlohmann::json reportJson(const TuneSummary& summary, const std::vector<SettingDimension>& space) {
    nlohmann::json lights = nlohmann::json::array();
    for (std::size_t i = 0; i < summary.choices.size(); ++i) {
        const LightChoice& choice = summary.choices[i];
        const evaluation::RankingTruth truth = summary.truths.at(i);
        nlohmann::json light = {{"light", summary.names[i]},
                                {"ranked_by", evaluation::rankedFigure(truth)},
                                {"before", measuredJson(choice.before, space, truth)},
                                {"after", measuredJson(choice.chosen, space, truth)},
                                {"changed", choice.changed}};
        nlohmann::json measured = nlohmann::json::array();
        if (i < summary.measured.size())
            for (const Measured& m : summary.measured[i]) measured.push_back(measuredJson(m, space, truth));
        light["measured"] = std::move(measured);
        if (const auto& fit = choice.offsetFit) {
            const auto offset = defaultOffset(fit->base);
            light["offset_fit"] = {{"setting", describe(fit->base, space)},
                                   {"default_offset", {offset[0], offset[1]}},
                                   {"default_normal_offset", fit->defaultNormalOffset},
                                   {"default", measuredJson(fit->atDefault, space, truth)},
                                   {"fitted_offset", fit->fitted.setting["polygon_offset"]},
                                   {"fitted_normal_offset", fit->fitted.setting["normal_offset"]},
                                   {"fitted", measuredJson(fit->fitted, space, truth)},
                                   {"lattice", latticeJson(*fit)}};
        }
        lights.push_back(std::move(light));
    }
    return {{"goal", summary.goal.kind == Goal::Kind::Budget ? "budget_ms" : "max_error"},
            {"limit", summary.goal.limit},
            {"views", summary.views},
            {"width", summary.width},
            {"height", summary.height},
            {"renders", summary.renders},
            {"grid_per_light", summary.gridPerLight},
            {"lights", lights}};
}

} // namespace shadowmap_tune
