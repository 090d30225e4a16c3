#include "engine/gl/Readback.h"

#include <cstddef>

namespace engine::gl {

namespace {

// glReadPixels has no DSA form: it reads the bound read framebuffer into the bound pack
// buffer. Bind ours, unbind any pack buffer, select the attachment, and put all of it back
// afterwards so a readback leaves the caller's state (and the framebuffer's) as it was.
template <typename Pixel>
std::vector<Pixel> readPixels(GLuint framebuffer, GLenum readBuffer, GLenum format, GLenum type,
                              int width, int height, int channels) {
    GLint previousFramebuffer = 0, previousPackBuffer = 0, previousAlignment = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &previousPackBuffer);
    glGetIntegerv(GL_PACK_ALIGNMENT, &previousAlignment);

    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    GLint previousReadBuffer = GL_NONE;
    glGetIntegerv(GL_READ_BUFFER, &previousReadBuffer);
    if (readBuffer != GL_NONE) glNamedFramebufferReadBuffer(framebuffer, readBuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    std::vector<Pixel> pixels(static_cast<std::size_t>(width) * height * channels);
    glReadnPixels(0, 0, width, height, format, type,
                  static_cast<GLsizei>(pixels.size() * sizeof(Pixel)), pixels.data());

    if (readBuffer != GL_NONE)
        glNamedFramebufferReadBuffer(framebuffer, static_cast<GLenum>(previousReadBuffer));
    glPixelStorei(GL_PACK_ALIGNMENT, previousAlignment);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(previousPackBuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    return pixels;
}

} // namespace

std::vector<std::uint8_t> readPixelsRGBA8(GLuint framebuffer, GLenum attachment, int width,
                                          int height) {
    return readPixels<std::uint8_t>(framebuffer, attachment, GL_RGBA, GL_UNSIGNED_BYTE, width,
                                    height, 4);
}

std::vector<float> readPixelsRGBA32F(GLuint framebuffer, GLenum attachment, int width,
                                     int height) {
    return readPixels<float>(framebuffer, attachment, GL_RGBA, GL_FLOAT, width, height, 4);
}

std::vector<float> readDepth32F(GLuint framebuffer, int width, int height) {
    // The depth attachment is read regardless of the read buffer: leave it alone.
    return readPixels<float>(framebuffer, GL_NONE, GL_DEPTH_COMPONENT, GL_FLOAT, width, height,
                             1);
}

} // namespace engine::gl
