// check-texel-density DENSITY.png
// The density view's screenshot read against the documented scale (docs/metrics.md, "Texel
// on screen"; truth/TexelDensityImage.h): every pixel is the no-value grey (128, 128, 128) or
// a colour of the scale's ramps, blue (0,0,255) -> green (0,255,0) -> yellow (255,255,0) ->
// red (255,0,0), one step of rounding allowed on the blue-green ramp. Prints the counts of
// grey, green-ish (m within [2^-0.5, 2]: green >= 128, red and blue <= 128) and off-scale
// pixels; exit 0 when none is off the scale and both grey and green-ish pixels are there (so
// the check saw a picture of the scale, not a blank one), else 1; 2 bad input.
#include "engine/util/OutputFile.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace {

bool grey(const std::uint8_t* p) { return p[0] == 128 && p[1] == 128 && p[2] == 128; }

bool onScale(const std::uint8_t* p) {
    const int r = p[0], g = p[1], b = p[2];
    return (r == 0 && std::abs(g + b - 255) <= 1) || (b == 0 && (g == 255 || r == 255));
}

bool greenish(const std::uint8_t* p) { return p[1] >= 128 && p[0] <= 128 && p[2] <= 128; }

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: check-texel-density DENSITY.png\n");
        return 2;
    }
    try {
        int width = 0, height = 0;
        const auto rgb = engine::readPng(argv[1], 3, width, height);
        std::size_t greys = 0, greens = 0, off = 0;
        for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
            const std::uint8_t* p = &rgb[i];
            greys += grey(p);
            greens += greenish(p);
            if (grey(p) || onScale(p)) continue;
            if (++off <= 5)
                std::printf("pixel (%zu, %zu) off the scale: (%d, %d, %d)\n", (i / 3) % width, (i / 3) / width, p[0],
                            p[1], p[2]);
        }
        std::printf("grey %zu, green-ish %zu, off the scale %zu of %zu pixels\n", greys, greens, off, rgb.size() / 3);
        return off == 0 && greys > 0 && greens > 0 ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "check-texel-density: %s\n", error.what());
        return 2;
    }
}
