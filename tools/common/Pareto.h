#pragma once
// The Pareto front of time against error, for any row type: the rows no other row beats in
// both (lower or equal in both, lower in one), sorted by time; ties in both keep the first.
// shadowmap-bench draws it, shadowmap-tune prunes its search with it.
#include <algorithm>
#include <vector>

namespace tools {

template <typename Row, typename TimeOf, typename ErrorOf>
std::vector<Row> paretoFront(const std::vector<Row>& rows, TimeOf timeOf, ErrorOf errorOf) {
    // Sorted by time (then error), a row is on the front iff its error is below every
    // error seen before it: the earlier rows are all at least as fast.
    std::vector<Row> sorted = rows;
    std::stable_sort(sorted.begin(), sorted.end(), [&](const Row& a, const Row& b) {
        return timeOf(a) != timeOf(b) ? timeOf(a) < timeOf(b) : errorOf(a) < errorOf(b);
    });
    std::vector<Row> front;
    for (const Row& row : sorted)
        if (front.empty() || errorOf(row) < errorOf(front.back())) front.push_back(row);
    return front;
}

} // namespace tools
