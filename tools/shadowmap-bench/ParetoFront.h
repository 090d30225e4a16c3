#pragma once
// Choosing settings from measured rows: the Pareto front of shadow time against error, and
// the most accurate setting within a time budget. "Error" here is BenchRow::rankedError():
// the soft error for a light with a size, else the area error, so a filter is judged by how
// well it shades partly lit pixels against the truth that models the light.
// Pure CPU, no I/O.
#include "BenchRow.h"

#include <optional>
#include <string>
#include <vector>

namespace shadowmap_bench {

// The rows of one light of one scene, in the order the sweep measured them.
struct LightRows {
    std::string scene, light;
    std::vector<BenchRow> rows;
};
std::vector<LightRows> groupByLight(const std::vector<BenchRow>& rows);

// The rows no other row beats in both time and error (lower or equal in both, lower in one),
// sorted by time: the settings worth considering at all. Ties in both keep the first.
std::vector<BenchRow> paretoFront(const std::vector<BenchRow>& rows);

// The lowest error among rows with shadowMs <= budgetMs (ties: the faster one); nullopt
// when no row fits.
std::optional<BenchRow> mostAccurateWithin(const std::vector<BenchRow>& rows, double budgetMs);

} // namespace shadowmap_bench
