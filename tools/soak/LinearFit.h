#pragma once
// Least-squares line through (x, y) samples: the soak's "how fast does it grow" number.
#include <vector>

namespace soak {

// The slope dy/dx of the least-squares line; 0 for fewer than two distinct x.
double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y);

} // namespace soak
