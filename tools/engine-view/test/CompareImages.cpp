// compare-images A.png B.png MAX_DIFF MIN_FRACTION [DIFF.png]
// Compares the RGB channels of two PNGs of the same size: a pixel agrees when every channel
// differs by at most MAX_DIFF (0-255). Prints the measured figures (max difference, mean
// absolute difference, fraction of agreeing pixels); exit 0 when at least MIN_FRACTION of
// the pixels agree, else 1 (and, given DIFF.png, writes the differences x16 there).
#include "engine/util/OutputFile.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    if (argc < 5 || argc > 6) {
        std::fprintf(stderr, "usage: compare-images A.png B.png MAX_DIFF MIN_FRACTION [DIFF.png]\n");
        return 2;
    }
    try {
        int wa = 0, ha = 0, wb = 0, hb = 0;
        const auto a = engine::readPng(argv[1], 3, wa, ha);
        const auto b = engine::readPng(argv[2], 3, wb, hb);
        if (wa != wb || ha != hb) {
            std::printf("size differs: %s is %dx%d, %s is %dx%d\n", argv[1], wa, ha, argv[2], wb, hb);
            return 1;
        }
        const int tolerance = std::atoi(argv[3]);
        const double minFraction = std::atof(argv[4]);
        const std::size_t pixels = static_cast<std::size_t>(wa) * ha;
        std::size_t agreeing = 0;
        int maxDiff = 0;
        double sum = 0.0;
        std::vector<std::uint8_t> diff(a.size());
        for (std::size_t i = 0; i < pixels; ++i) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(a[3 * i + c]) - int(b[3 * i + c]));
                worst = std::max(worst, d);
                sum += d;
                diff[3 * i + c] = static_cast<std::uint8_t>(std::min(255, d * 16));
            }
            maxDiff = std::max(maxDiff, worst);
            agreeing += worst <= tolerance;
        }
        const double fraction = static_cast<double>(agreeing) / static_cast<double>(pixels);
        std::printf("%s vs %s: %dx%d, max diff %d/255, mean abs diff %.5f/255, %.4f%% of pixels within %d/255 "
                    "(need %.4f%%)\n",
                    argv[1], argv[2], wa, ha, maxDiff, sum / (3.0 * pixels), 100.0 * fraction, tolerance,
                    100.0 * minFraction);
        if (fraction >= minFraction) return 0;
        if (argc == 6) engine::writePngAtomically(argv[5], wa, ha, 3, diff);
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "compare-images: %s\n", error.what());
        return 2;
    }
}
