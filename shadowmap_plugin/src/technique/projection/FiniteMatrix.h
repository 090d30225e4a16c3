#pragma once
// What the lookup uploads must be finite: a light whose eye planes (or eye-space position)
// are not loses its shadow, loudly, instead of shading with NaN.
#include <glm/glm.hpp>

#include <cmath>

namespace shadowmap {

inline bool isFinite(const glm::mat4& matrix) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(matrix[c][r])) return false;
    return true;
}

} // namespace shadowmap
