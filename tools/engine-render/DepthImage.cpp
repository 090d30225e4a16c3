#include "DepthImage.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <limits>
#include <string>

std::vector<std::uint8_t> depthToGray(const engine::DepthReadback& map, int& width, int& height) {
    width = map.width * map.layers;
    height = map.height;
    float nearest = std::numeric_limits<float>::max(), farthest = 0.0f;
    for (float depth : map.depth)
        if (depth < 1.0f) {
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
        }
    const float range = std::max(farthest - nearest, 1e-12f);
    std::vector<std::uint8_t> gray(static_cast<std::size_t>(width) * height);
    for (int layer = 0; layer < map.layers; ++layer)
        for (int y = 0; y < map.height; ++y)
            for (int x = 0; x < map.width; ++x) {
                const float depth =
                    map.depth[(static_cast<std::size_t>(layer) * map.height + y) * map.width + x];
                gray[static_cast<std::size_t>(y) * width + layer * map.width + x] =
                    depth >= 1.0f ? 255
                                  : static_cast<std::uint8_t>(230.0f * (depth - nearest) / range + 0.5f);
            }
    return gray;
}

const char* const kCubeFaceNames[engine::kCubeFaces] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

namespace {

// stb_easy_font's vertex: x, y, z floats and 4 colour bytes; 4 per axis-aligned quad.
struct FontVertex {
    float x, y, z;
    unsigned char color[4];
};

void fill(std::vector<std::uint8_t>& gray, int width, int height, int x0, int y0, int x1, int y1,
          std::uint8_t value) {
    for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) gray[static_cast<std::size_t>(y) * width + x] = value;
}

} // namespace

void labelCubeFaces(std::vector<std::uint8_t>& gray, int width, int height, int faceWidth) {
    // stb_easy_font's glyphs are 7 units tall: scale them to about 1/20 of the face (at
    // least 1 pixel per unit), so the label reads at a 1024 face and at a 64 one alike.
    const int scale = std::max(1, std::min(faceWidth, height) / 140);
    const int margin = 2 * scale;
    for (int face = 0; face < engine::kCubeFaces && (face + 1) * faceWidth <= width; ++face) {
        std::string text = kCubeFaceNames[face];  // stb_easy_font wants a mutable char*
        FontVertex quads[64 * 4];
        unsigned char black[4] = {0, 0, 0, 255};
        const int count = stb_easy_font_print(0.0f, 0.0f, text.data(), black, quads, sizeof quads);
        const int left = face * faceWidth;
        const int boxWidth = stb_easy_font_width(text.data()) * scale + 2 * margin;
        const int boxHeight = 7 * scale + 2 * margin;
        fill(gray, width, height, left, 0, left + boxWidth, boxHeight, 255);
        for (int q = 0; q < count; ++q) {
            const FontVertex& a = quads[4 * q];
            const FontVertex& b = quads[4 * q + 2];  // the opposite corner
            fill(gray, width, height, left + margin + static_cast<int>(a.x) * scale, margin + static_cast<int>(a.y) * scale,
                 left + margin + static_cast<int>(b.x) * scale, margin + static_cast<int>(b.y) * scale, 0);
        }
        if (face > 0) fill(gray, width, height, left, 0, left + 1, height, 0);  // the seam between faces
    }
}
