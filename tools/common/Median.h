#pragma once
// The tools' summaries of repeated timings: the median (robust to the odd slow frame a
// shared machine gives) and the tail beside it (a hitch is a bug, and the median hides it).
#include <vector>

namespace tools {

// Mean of the two middle values for an even count; 0 for none.
double median(std::vector<double> values);

// The nearest-rank percentile: the smallest value with at least `fraction` of the values at
// or below it (fraction in (0, 1]; 1 gives the maximum). 0 for none. Nearest rank, not
// interpolation: a p99 over 60 frames is then a frame that happened.
double percentile(std::vector<double> values, double fraction);

// What every frame-time report prints: median, p99 and max, in the values' unit.
struct TimeSummary {
    double median = 0.0;
    double p99 = 0.0;
    double max = 0.0;
};
TimeSummary summarizeTimes(const std::vector<double>& values);

} // namespace tools
