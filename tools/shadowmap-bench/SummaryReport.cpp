#include "SummaryReport.h"

#include "ParetoFront.h"

#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string_view>

namespace shadowmap_bench {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// Concatenation by appending: GCC 12 reports a false -Wrestrict on "literal" + temporary.
std::string concat(std::initializer_list<std::string_view> parts) {
    std::string text;
    for (std::string_view part : parts) text += part;
    return text;
}

std::string budgetName(double budgetMs) {
    return budgetMs == std::numeric_limits<double>::infinity() ? "any time" : concat({"≤ ", format("%g", budgetMs), " ms"});
}

// "woo 2048 d24 pcf (0.08 %)" (its ranked error), or a dash when nothing fits the budget.
std::string bestCell(const std::vector<BenchRow>& rows, double budgetMs) {
    const auto best = mostAccurateWithin(rows, budgetMs);
    return best ? concat({best->label(), " (", format("%.3f", best->rankedError()), " %)"}) : "—";
}

// A figure only some rows have (a sized light's soft error): a dash on the others.
std::string optionalCell(const std::optional<double>& value) { return value ? format("%.3f", *value) : "—"; }

std::string atAGlance(const std::vector<LightRows>& lights) {
    std::vector<double> budgets = kTimeBudgetsMs;
    budgets.push_back(std::numeric_limits<double>::infinity());
    std::string text = "| scene | light |";
    std::string rule = "|---|---|";
    for (double budget : budgets) {
        text += concat({" ", budgetName(budget), " |"});
        rule += "---|";
    }
    text += "\n" + rule + "\n";
    for (const LightRows& light : lights) {
        text += concat({"| ", light.scene, " | ", light.light, " |"});
        for (double budget : budgets) text += concat({" ", bestCell(light.rows, budget), " |"});
        text += "\n";
    }
    return text;
}

std::string rowCells(const BenchRow& row) {
    return concat({" ", row.label(), " | ", format("%.2f", row.shadowMs), " | ",
                   format("%.3f", row.acne), " | ", format("%.3f", row.leak), " | ",
                   format("%.3f", row.error), " | ", format("%.3f", row.errorNoEdge), " | ",
                   format("%.3f", row.areaError), " | ", optionalCell(row.softError), " | ",
                   optionalCell(row.penumbraError), " |"});
}

// The figures rowCells gives, as the tables' header and rule after their first columns.
constexpr const char* kFigureHeader =
    " shadow ms | acne % | leak % | error % | error off edges % | area error % | soft error % | penumbra error % |\n";
constexpr const char* kFigureRule = "---|---|---|---|---|---|---|---|\n";

std::string lightSection(const LightRows& light) {
    std::string text = concat({"## ", light.scene, " / ", light.light, "\n\n"});
    text += "Most accurate setting within a budget of shadow time:\n\n";
    text += concat({"| budget | setting |", kFigureHeader, "|---|---|", kFigureRule});
    for (double budget : kTimeBudgetsMs) {
        const auto best = mostAccurateWithin(light.rows, budget);
        text += concat({"| ", budgetName(budget), " |", best ? rowCells(*best) : " — (nothing this fast) | | | | | | | | |", "\n"});
    }
    text += "\nPareto front (no other setting is both faster and more accurate), fastest first:\n\n";
    text += concat({"| setting |", kFigureHeader, "|---|", kFigureRule});
    for (const BenchRow& row : paretoFront(light.rows)) text += concat({"|", rowCells(row), "\n"});
    return text + "\n";
}

} // namespace

std::string summaryMarkdown(const std::vector<BenchRow>& rows, const SweepDescription& sweep) {
    const std::vector<LightRows> lights = groupByLight(rows);
    std::string text = "# shadowmap-bench summary\n\n";
    text += concat({std::to_string(sweep.width), "×", std::to_string(sweep.height), ", ",
                    std::to_string(sweep.frames)});
    text += " timed frame(s) per setting, each setting applied to every light of the scene. "
            "Shadow ms: median wall time of the light's shadow passes, each closed by glFinish. "
            "Errors: percent of the light's evaluation set against Embree ray-traced shadows "
            "(docs/metrics.md); \"off edges\" leaves out pixels within 1 px of a true shadow edge. "
            "\"Area error\" scores the shade against the lit fraction of each pixel (16 shadow rays "
            "over its footprint), so a filter's partial shade where an edge really crosses a pixel "
            "is not counted as error. \"Soft error\" (lights with a size only) is the mean |shade − "
            "truth| against the soft truth, the visible fraction of the light from each pixel's point, "
            "and \"penumbra error\" the same where truth or shade lies strictly between 0 and 1 "
            "(docs/soft-shadows.md). Ranking: a light with a size (light_size > 0) is ranked by its "
            "soft error, the truth that models that light; a point light by its area error. "
            "A setting's label adds what the sweep set and the light's size: size (radius or angular "
            "diameter), fr (filter radius: pcf's disk, vsm's and evsm's blur), taps, br (bleed reduction), "
            "no (normal offset), and for a directional light its "
            "projection (uniform, lispsm), c (cascades: a count or auto) and stable or unstable.\n\n";
    text += concat({"Machine: ", sweep.cpuModel, ", ", std::to_string(sweep.cores), " cores; ", sweep.glRenderer,
                    ", ", sweep.glVersion, ". Sweep wall time: ", format("%.0f", sweep.seconds), " s.\n\n"});
    text += "Most accurate setting (soft error % for a sized light, else area error %) within each budget "
            "of shadow time per frame:\n\n";
    text += atAGlance(lights) + "\n";
    for (const LightRows& light : lights) text += lightSection(light);
    return text;
}

} // namespace shadowmap_bench
