#pragma once
// An 8-bit RGBA picture, top row first (as Renderer::readColor returns and PNGs store).
#include <cstdint>
#include <vector>

namespace engine_view {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4

    bool empty() const { return width <= 0 || height <= 0; }
    static Image fromGray(int width, int height, const std::vector<std::uint8_t>& gray) {
        Image image{width, height, std::vector<std::uint8_t>(gray.size() * 4)};
        for (std::size_t i = 0; i < gray.size(); ++i) {
            image.rgba[4 * i] = image.rgba[4 * i + 1] = image.rgba[4 * i + 2] = gray[i];
            image.rgba[4 * i + 3] = 255;
        }
        return image;
    }
};

} // namespace engine_view
