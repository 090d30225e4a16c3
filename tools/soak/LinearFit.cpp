#include "LinearFit.h"

#include <cassert>
#include <cstddef>

namespace soak {

double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y) {
    assert(x.size() == y.size());
    const double n = static_cast<double>(x.size());
    if (x.size() < 2) return 0.0;
    double meanX = 0.0, meanY = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        meanX += x[i] / n;
        meanY += y[i] / n;
    }
    // Centred sums: no cancellation between large frame numbers or RSS values.
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - meanX) * (y[i] - meanY);
        sxx += (x[i] - meanX) * (x[i] - meanX);
    }
    return sxx > 0.0 ? sxy / sxx : 0.0;
}

} // namespace soak
