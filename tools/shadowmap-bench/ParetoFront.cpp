#include "ParetoFront.h"

#include "Pareto.h"

#include <algorithm>

namespace shadowmap_bench {

std::vector<LightRows> groupByLight(const std::vector<BenchRow>& rows) {
    std::vector<LightRows> groups;
    for (const BenchRow& row : rows) {
        auto group = std::find_if(groups.begin(), groups.end(), [&](const LightRows& g) {
            return g.scene == row.scene && g.light == row.light;
        });
        if (group == groups.end()) group = groups.insert(groups.end(), LightRows{row.scene, row.light, {}});
        group->rows.push_back(row);
    }
    return groups;
}

std::vector<BenchRow> paretoFront(const std::vector<BenchRow>& rows) {
    return tools::paretoFront(rows, [](const BenchRow& row) { return row.shadowMs; },
                              [](const BenchRow& row) { return row.rankedError(); });
}

std::optional<BenchRow> mostAccurateWithin(const std::vector<BenchRow>& rows, double budgetMs) {
    std::optional<BenchRow> best;
    for (const BenchRow& row : rows) {
        if (row.shadowMs > budgetMs) continue;
        if (!best || row.rankedError() < best->rankedError() ||
            (row.rankedError() == best->rankedError() && row.shadowMs < best->shadowMs))
            best = row;
    }
    return best;
}

} // namespace shadowmap_bench
