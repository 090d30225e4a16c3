#pragma once
// Numbers in messages, one way everywhere: as people write them (0.5, 2, -1, 1e+30; not
// 0.500000 or 5.000000), nine significant digits, enough to tell any two floats apart.
#include <cstdio>
#include <string>

namespace engine {

inline std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

} // namespace engine
