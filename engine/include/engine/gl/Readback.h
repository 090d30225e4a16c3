#pragma once
// Readback: copies a framebuffer's pixels to the CPU, for tests, tools and image output.
// Rows come bottom-up, as GL stores them (row 0 is the bottom of the image): flip before
// writing an image file. Blocks until rendering is done; not for per-frame use.
#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace engine::gl {

// w×h RGBA8 pixels (4 bytes each) of colour `attachment` (GL_COLOR_ATTACHMENTi, or GL_BACK
// for framebuffer 0).
std::vector<std::uint8_t> readPixelsRGBA8(GLuint framebuffer, GLenum attachment, int width,
                                          int height);

// w×h RGBA float pixels (4 floats each), unclamped for float attachments.
std::vector<float> readPixelsRGBA32F(GLuint framebuffer, GLenum attachment, int width,
                                     int height);

// w×h depth values in [0,1] (or raw for GL_DEPTH_COMPONENT32F) of the depth attachment.
std::vector<float> readDepth32F(GLuint framebuffer, int width, int height);

} // namespace engine::gl
