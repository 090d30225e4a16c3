#include "Median.h"

#include <algorithm>

namespace tools {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    if (values.size() % 2) return values[mid];
    const double upper = values[mid];
    return 0.5 * (*std::max_element(values.begin(), values.begin() + mid) + upper);
}

} // namespace tools
