#include "engine/render/TextureReadback.h"

#include <algorithm>

namespace engine {

namespace {

template <typename T>
std::vector<T> readTopDown(const gl::Texture& texture, GLenum format, GLenum type, int channels) {
    const int width = texture.width(), height = texture.height();
    const std::size_t rowElements = static_cast<std::size_t>(width) * channels;
    std::vector<T> pixels(rowElements * height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(pixels.size() * sizeof(T)),
                      pixels.data());
    for (int row = 0; row < height / 2; ++row)
        std::swap_ranges(pixels.begin() + row * rowElements, pixels.begin() + (row + 1) * rowElements,
                         pixels.begin() + (height - 1 - row) * rowElements);
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
    return readTopDown<std::uint8_t>(texture, GL_RGBA, GL_UNSIGNED_BYTE, 4);
}

std::vector<float> readTextureFloatTopDown(const gl::Texture& texture, int channels) {
    return readTopDown<float>(texture, formatForChannels(channels), GL_FLOAT, channels);
}

} // namespace engine
