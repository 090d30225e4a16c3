#include "engine/render/TextureReadback.h"

#include <algorithm>

namespace engine {

namespace {

template <typename T>
std::vector<T> readTopDown(unsigned texture, int width, int height, int layers, GLenum format,
                           GLenum type, int channels) {
    const std::size_t rowElements = static_cast<std::size_t>(width) * channels;
    std::vector<T> pixels(rowElements * height * layers);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture, 0, format, type, static_cast<GLsizei>(pixels.size() * sizeof(T)),
                      pixels.data());
    for (int layer = 0; layer < layers; ++layer) {
        const auto first = pixels.begin() + layer * rowElements * height;
        for (int row = 0; row < height / 2; ++row)
            std::swap_ranges(first + row * rowElements, first + (row + 1) * rowElements,
                             first + (height - 1 - row) * rowElements);
    }
    return pixels;
}

GLenum formatForChannels(int channels) {
    switch (channels) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    default: return GL_RGBA;
    }
}

} // namespace

std::vector<std::uint8_t> readTextureRGBA8TopDown(const gl::Texture& texture) {
    return readTopDown<std::uint8_t>(texture.id(), texture.width(), texture.height(), 1, GL_RGBA,
                                     GL_UNSIGNED_BYTE, 4);
}

std::vector<float> readTextureFloatTopDown(const gl::Texture& texture, int channels) {
    return readTopDown<float>(texture.id(), texture.width(), texture.height(), 1,
                              formatForChannels(channels), GL_FLOAT, channels);
}

std::vector<float> readDepthLayersTopDown(unsigned texture, int width, int height, int layers) {
    return readTopDown<float>(texture, width, height, layers, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
}

std::vector<std::uint8_t> readR8TopDown(unsigned texture, int width, int height) {
    return readTopDown<std::uint8_t>(texture, width, height, 1, GL_RED, GL_UNSIGNED_BYTE, 1);
}

} // namespace engine
