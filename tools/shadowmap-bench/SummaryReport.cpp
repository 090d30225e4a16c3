#include "SummaryReport.h"

#include "ParetoFront.h"

#include <cstdio>
#include <initializer_list>
#include <limits>
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

// "woo 2048 d24 pcf (0.08 %)", or a dash when nothing fits the budget.
std::string bestCell(const std::vector<BenchRow>& rows, double budgetMs) {
    const auto best = mostAccurateWithin(rows, budgetMs);
    return best ? concat({best->setting.label(), " (", format("%.3f", best->areaError), " %)"}) : "—";
}

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
    return concat({" ", row.setting.label(), " | ", format("%.2f", row.shadowMs), " | ",
                   format("%.3f", row.acne), " | ", format("%.3f", row.leak), " | ",
                   format("%.3f", row.error), " | ", format("%.3f", row.errorNoEdge), " | ",
                   format("%.3f", row.areaError), " |"});
}

std::string lightSection(const LightRows& light) {
    std::string text = concat({"## ", light.scene, " / ", light.light, "\n\n"});
    text += "Most accurate setting within a budget of shadow time:\n\n";
    text += "| budget | setting | shadow ms | acne % | leak % | error % | error off edges % | area error % |\n";
    text += "|---|---|---|---|---|---|---|---|\n";
    for (double budget : kTimeBudgetsMs) {
        const auto best = mostAccurateWithin(light.rows, budget);
        text += concat({"| ", budgetName(budget), " |", best ? rowCells(*best) : " — (nothing this fast) | | | | | | |", "\n"});
    }
    text += "\nPareto front (no other setting is both faster and more accurate), fastest first:\n\n";
    text += "| setting | shadow ms | acne % | leak % | error % | error off edges % | area error % |\n";
    text += "|---|---|---|---|---|---|---|\n";
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
            "is not counted as error; settings are ranked by it.\n\n";
    text += concat({"Machine: ", sweep.cpuModel, ", ", std::to_string(sweep.cores), " cores; ", sweep.glRenderer,
                    ", ", sweep.glVersion, ". Sweep wall time: ", format("%.0f", sweep.seconds), " s.\n\n"});
    text += "Most accurate setting (area error %) within each budget of shadow time per frame:\n\n";
    text += atAGlance(lights) + "\n";
    for (const LightRows& light : lights) text += lightSection(light);
    return text;
}

} // namespace shadowmap_bench
