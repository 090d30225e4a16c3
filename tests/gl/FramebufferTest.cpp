// Offscreen targets: clears read back exactly, incomplete targets are named, depth formats
// and cube faces used by shadow maps attach.
#include "GlTestContext.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Readback.h"
#include "engine/gl/Texture.h"

#include <algorithm>
#include <cmath>

namespace engine::gl {
namespace {

using FramebufferTest = test::GlTest;

Framebuffer colorTarget(const Texture& color) {
    Framebuffer framebuffer = Framebuffer::create();
    framebuffer.attach(GL_COLOR_ATTACHMENT0, color);
    framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    framebuffer.requireComplete("test colour target");
    return framebuffer;
}

TEST_F(FramebufferTest, ClearColourReadsBackExactly) {
    // Not square, so a swapped width/height would show.
    const Texture color = Texture::create2D(GL_RGBA8, 32, 16);
    const Framebuffer framebuffer = colorTarget(color);
    // k/255 values: exactly representable in RGBA8, so the readback must be exact.
    const GLfloat clear[] = {51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 1.0f};
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);

    const auto pixels = readPixelsRGBA8(framebuffer.id(), GL_COLOR_ATTACHMENT0, 32, 16);
    ASSERT_EQ(pixels.size(), 32u * 16u * 4u);
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
        ASSERT_EQ(pixels[i + 0], 51) << "pixel " << i / 4;
        ASSERT_EQ(pixels[i + 1], 102) << "pixel " << i / 4;
        ASSERT_EQ(pixels[i + 2], 153) << "pixel " << i / 4;
        ASSERT_EQ(pixels[i + 3], 255) << "pixel " << i / 4;
    }
}

TEST_F(FramebufferTest, FloatReadbackIsUnclamped) {
    const Texture color = Texture::create2D(GL_RGBA32F, 4, 4);
    const Framebuffer framebuffer = colorTarget(color);
    const GLfloat clear[] = {1.5f, -2.0f, 1e6f, 0.25f};
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);

    const auto pixels = readPixelsRGBA32F(framebuffer.id(), GL_COLOR_ATTACHMENT0, 4, 4);
    ASSERT_EQ(pixels.size(), 4u * 4u * 4u);
    for (std::size_t i = 0; i < pixels.size(); ++i) EXPECT_EQ(pixels[i], clear[i % 4]);
}

TEST_F(FramebufferTest, ReadbackLeavesBindingsAsTheyWere) {
    const Texture color = Texture::create2D(GL_RGBA8, 4, 4);
    const Framebuffer framebuffer = colorTarget(color);
    const Framebuffer other = colorTarget(color);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, other.id());

    readPixelsRGBA8(framebuffer.id(), GL_COLOR_ATTACHMENT0, 4, 4);

    GLint bound = 0, alignment = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &bound);
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    EXPECT_EQ(static_cast<GLuint>(bound), other.id());
    EXPECT_EQ(alignment, 4); // GL's default
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

TEST_F(FramebufferTest, IncompleteFramebufferThrowsNamingTheTarget) {
    const Framebuffer empty = Framebuffer::create();
    try {
        empty.requireComplete("shadow map of light 'sun'");
        FAIL() << "an empty framebuffer passed as complete";
    } catch (const GlError& error) {
        EXPECT_STREQ(error.what(), "Framebuffer 'shadow map of light 'sun'' is incomplete: "
                                   "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT");
    }
}

// Depth-only target (a shadow map): no colour buffer to draw to or read from.
Framebuffer depthTarget(const Texture& depth) {
    Framebuffer framebuffer = Framebuffer::create();
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    framebuffer.setDrawBuffers({GL_NONE});
    framebuffer.setReadBuffer(GL_NONE);
    return framebuffer;
}

class DepthFormatTest : public test::GlTest, public testing::WithParamInterface<GLenum> {};

TEST_P(DepthFormatTest, IsCreatableAttachableAndClears) {
    const GLenum format = GetParam();
    const Texture depth = Texture::create2D(format, 16, 8);
    EXPECT_EQ(depth.internalFormat(), format);
    const Framebuffer framebuffer = depthTarget(depth);
    ASSERT_NO_THROW(framebuffer.requireComplete("depth-only target"));

    const GLfloat clear = 0.25f; // exact in every depth format (a power of two)
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &clear);
    const auto depths = readDepth32F(framebuffer.id(), 16, 8);
    ASSERT_EQ(depths.size(), 16u * 8u);
    // Unorm formats store round(0.25·(2ⁿ−1)), which is 0.25 within one step of 2⁻ⁿ.
    const float step = format == GL_DEPTH_COMPONENT16 ? 1.0f / 65535 : 1.0f / 16777215;
    for (const float value : depths) ASSERT_NEAR(value, clear, step);
}

INSTANTIATE_TEST_SUITE_P(ShadowMapFormats, DepthFormatTest,
                         testing::Values(GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                         GL_DEPTH_COMPONENT32F),
                         [](const testing::TestParamInfo<GLenum>& info) {
                             switch (info.param) {
                             case GL_DEPTH_COMPONENT16: return "d16";
                             case GL_DEPTH_COMPONENT24: return "d24";
                             default: return "d32f";
                             }
                         });

TEST_F(FramebufferTest, CubeFacesAttachAsSeparateLayers) {
    const Texture cube = Texture::createCube(GL_DEPTH_COMPONENT32F, 8);
    Framebuffer framebuffer = depthTarget(cube);
    for (int face = 0; face < 6; ++face) {
        framebuffer.attachLayer(GL_DEPTH_ATTACHMENT, cube, face);
        framebuffer.requireComplete("cube face " + std::to_string(face));
        const GLfloat clear = 0.125f * static_cast<float>(face + 1);
        glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &clear);
    }
    // Each face kept its own value: the layers really are different faces.
    for (int face = 0; face < 6; ++face) {
        framebuffer.attachLayer(GL_DEPTH_ATTACHMENT, cube, face);
        const auto depths = readDepth32F(framebuffer.id(), 8, 8);
        EXPECT_EQ(depths.front(), 0.125f * static_cast<float>(face + 1)) << "face " << face;
    }
}

} // namespace
} // namespace engine::gl
