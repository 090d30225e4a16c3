#include "Median.h"

#include <algorithm>
#include <cmath>

namespace tools {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    if (values.size() % 2) return values[mid];
    const double upper = values[mid];
    return 0.5 * (*std::max_element(values.begin(), values.begin() + mid) + upper);
}

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    const double clamped = std::clamp(fraction, 0.0, 1.0);
    // The small slack keeps a product like 0.99 * 200 that lands a rounding step above a whole
    // number on that number, not on the next rank.
    const double exactRank = clamped * static_cast<double>(values.size());
    const auto rank = static_cast<std::size_t>(std::ceil(exactRank - 1e-9));
    const std::size_t index = rank == 0 ? 0 : rank - 1;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
    return values[index];
}

TimeSummary summarizeTimes(const std::vector<double>& values) {
    return {median(values), percentile(values, 0.99), percentile(values, 1.0)};
}

} // namespace tools
