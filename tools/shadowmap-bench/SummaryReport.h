#pragma once
// summary.md: per light, the most accurate setting within a few shadow-time budgets, and
// the Pareto front of time against error as a table; an at-a-glance table on top.
#include "BenchRow.h"

#include <string>
#include <vector>

namespace shadowmap_bench {

// Where and how the numbers were measured, printed at the top of the summary.
struct SweepDescription {
    int width = 0, height = 0, frames = 0;
    std::string glRenderer, glVersion;
    std::string cpuModel;
    int cores = 0;
    double seconds = 0.0;  // wall time of the whole sweep
};

// The budgets of the summary, in milliseconds of shadow passes per light and frame: 2-20
// suit the showcase's lights, 50 a 100k-triangle model like 2CylinderEngine on llvmpipe.
inline const std::vector<double> kTimeBudgetsMs = {2.0, 5.0, 10.0, 20.0, 50.0};

std::string summaryMarkdown(const std::vector<BenchRow>& rows, const SweepDescription& sweep);

} // namespace shadowmap_bench
