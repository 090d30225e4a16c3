#include "ParetoFront.h"

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
    // Sorted by time (then area error), a row is on the front iff its error is below every
    // error seen before it: the earlier rows are all at least as fast.
    std::vector<BenchRow> sorted = rows;
    std::stable_sort(sorted.begin(), sorted.end(), [](const BenchRow& a, const BenchRow& b) {
        return a.shadowMs != b.shadowMs ? a.shadowMs < b.shadowMs : a.areaError < b.areaError;
    });
    std::vector<BenchRow> front;
    for (const BenchRow& row : sorted)
        if (front.empty() || row.areaError < front.back().areaError) front.push_back(row);
    return front;
}

std::optional<BenchRow> mostAccurateWithin(const std::vector<BenchRow>& rows, double budgetMs) {
    std::optional<BenchRow> best;
    for (const BenchRow& row : rows) {
        if (row.shadowMs > budgetMs) continue;
        if (!best || row.areaError < best->areaError ||
            (row.areaError == best->areaError && row.shadowMs < best->shadowMs))
            best = row;
    }
    return best;
}

} // namespace shadowmap_bench
