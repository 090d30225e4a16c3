#include "Presenter.h"

#include "engine/gl/Readback.h"
#include "engine/util/OutputFile.h"

#include <algorithm>
#include <cmath>

namespace engine_view {

void Presenter::present(const Image& image, int width, int height) {
    if (!texture_.id() || texture_.width() != image.width || texture_.height() != image.height) {
        texture_ = engine::gl::Texture::create2D(GL_RGBA8, image.width, image.height);
        framebuffer_ = engine::gl::Framebuffer::create();
        framebuffer_.attach(GL_COLOR_ATTACHMENT0, texture_);
        framebuffer_.setReadBuffer(GL_COLOR_ATTACHMENT0);
        framebuffer_.requireComplete("engine-view's presented image");
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the texture holds the image's top row; the blit below turns it upright.
    glTextureSubImage2D(texture_.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_FRAMEBUFFER_SRGB);  // the bytes are sRGB already: copy them as they are
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, width, height);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    // Fit, keeping the aspect ratio; exactly 1:1 when the sizes agree.
    const double scale = std::min(static_cast<double>(width) / image.width, static_cast<double>(height) / image.height);
    const int w = std::max(1, static_cast<int>(std::lround(image.width * scale)));
    const int h = std::max(1, static_cast<int>(std::lround(image.height * scale)));
    const int x0 = (width - w) / 2, y0 = (height - h) / 2;
    glBlitNamedFramebuffer(framebuffer_.id(), 0, 0, 0, image.width, image.height,
                           x0, y0 + h, x0 + w, y0,  // destination rows reversed: top row at the top
                           GL_COLOR_BUFFER_BIT, scale >= 1.0 ? GL_NEAREST : GL_LINEAR);
}

Image Presenter::readWindow(int width, int height) const {
    const std::vector<std::uint8_t> bottomUp = engine::gl::readPixelsRGBA8(0, GL_BACK, width, height);
    Image image{width, height, std::vector<std::uint8_t>(bottomUp.size())};
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(bottomUp.begin() + (height - 1 - y) * row, row, image.rgba.begin() + y * row);
    return image;
}

void Presenter::screenshot(const std::filesystem::path& path, int width, int height) const {
    const Image image = readWindow(width, height);
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
    for (std::size_t i = 0; i < rgb.size() / 3; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
    engine::writePngAtomically(path, width, height, 3, rgb);
}

} // namespace engine_view
