// check-penumbra PENUMBRA.png SHADOW.png MIN_PIXELS
// The penumbra view's screenshot against the shadow view's of the same light and frame:
// a pixel must be penumbra-coloured exactly where the shadow term (the shadow view's gray)
// lies strictly between 0 and 255. Penumbra-coloured: red and blue at least 128, green below
// 128 (the view tints partly lit pixels 70% magenta, so red and blue >= 178 and green <= 77,
// and dims every other pixel to 30%, so every channel <= 77). Prints the penumbra's pixel
// count; exit 0 when every pixel agrees and the penumbra has at least MIN_PIXELS pixels and
// is not the whole picture (so the check compared both kinds), else 1; 2 bad input.
#include "engine/util/OutputFile.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace {

bool penumbraColoured(const std::uint8_t* rgb) { return rgb[0] >= 128 && rgb[2] >= 128 && rgb[1] < 128; }

bool partlyLit(std::uint8_t gray) { return gray > 0 && gray < 255; }

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: check-penumbra PENUMBRA.png SHADOW.png MIN_PIXELS\n");
        return 2;
    }
    try {
        int wp = 0, hp = 0, ws = 0, hs = 0;
        const auto view = engine::readPng(argv[1], 3, wp, hp);
        const auto shadow = engine::readPng(argv[2], 3, ws, hs);
        if (wp != ws || hp != hs) {
            std::printf("size differs: %s is %dx%d, %s is %dx%d\n", argv[1], wp, hp, argv[2], ws, hs);
            return 1;
        }
        const std::size_t pixels = static_cast<std::size_t>(wp) * hp;
        std::size_t penumbra = 0, wrong = 0;
        for (std::size_t i = 0; i < pixels; ++i) {
            const bool expected = partlyLit(shadow[3 * i]);
            penumbra += expected;
            if (penumbraColoured(&view[3 * i]) == expected) continue;
            if (++wrong <= 5)
                std::printf("pixel (%zu, %zu): shadow term %d, view (%d, %d, %d)\n", i % wp, i / wp, shadow[3 * i],
                            view[3 * i], view[3 * i + 1], view[3 * i + 2]);
        }
        const std::size_t minimum = std::strtoul(argv[3], nullptr, 10);
        std::printf("penumbra %zu pixels of %zu, %zu disagree\n", penumbra, pixels, wrong);
        return wrong == 0 && penumbra >= minimum && penumbra < pixels ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "check-penumbra: %s\n", error.what());
        return 2;
    }
}
