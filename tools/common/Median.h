#pragma once
// The tools' one summary of repeated timings: the median (robust to the odd slow frame a
// shared machine gives). Mean of the two middle values for an even count; 0 for none.
#include <vector>

namespace tools {

double median(std::vector<double> values);

} // namespace tools
