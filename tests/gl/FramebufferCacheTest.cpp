// FramebufferCache: one framebuffer per target set, reused across frames, and none left
// behind by a deleted texture.
#include "GlTestContext.h"

#include "engine/gl/FramebufferCache.h"
#include "engine/gl/Texture.h"

#include <vector>

using engine::gl::FramebufferCache;
using engine::gl::Texture;

namespace {

// Clears the framebuffer's depth to `depth` and reads the texture back: did the clear land
// in this texture?
float clearAndRead(const engine::gl::Framebuffer& framebuffer, const Texture& texture, float depth) {
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &depth);
    std::vector<float> texels(static_cast<std::size_t>(texture.width()) * texture.height());
    glGetTextureImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    return texels.front();
}

GLint drawBufferOf(const engine::gl::Framebuffer& framebuffer) {
    framebuffer.bind();
    GLint drawBuffer = -1;
    glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return drawBuffer;
}

} // namespace

class FramebufferCacheTest : public engine::test::GlTest {};

TEST_F(FramebufferCacheTest, TheSameTargetsReuseOneFramebuffer) {
    FramebufferCache cache;
    const Texture cube = Texture::createCube(GL_DEPTH_COMPONENT24, 4);
    const GLuint face0 = cache.get({{GL_DEPTH_ATTACHMENT, cube.id(), 0}}, "face 0").id();
    const GLuint face1 = cache.get({{GL_DEPTH_ATTACHMENT, cube.id(), 1}}, "face 1").id();
    EXPECT_NE(face0, face1) << "another layer is another target";
    EXPECT_EQ(cache.get({{GL_DEPTH_ATTACHMENT, cube.id(), 0}}, "face 0").id(), face0);
    EXPECT_EQ(cache.created(), 2u) << "the second frame made framebuffers again";
}

TEST_F(FramebufferCacheTest, ColourTargetsDrawInTheOrderGiven) {
    FramebufferCache cache;
    const Texture colour = Texture::create2D(GL_RGBA8, 4, 4);
    const Texture depth = Texture::create2D(GL_DEPTH_COMPONENT32F, 4, 4);
    const auto& framebuffer =
        cache.get({{GL_COLOR_ATTACHMENT0, colour.id()}, {GL_DEPTH_ATTACHMENT, depth.id()}}, "lit");
    EXPECT_EQ(drawBufferOf(framebuffer), GL_COLOR_ATTACHMENT0);
    const auto& depthOnly = cache.get({{GL_DEPTH_ATTACHMENT, depth.id()}}, "depth only");
    EXPECT_EQ(drawBufferOf(depthOnly), GL_NONE);
}

// Entries are keyed by texture name, and GL may hand a deleted texture's name to a new
// texture: dropping the entry when the texture dies is what keeps a later lookup from
// returning a framebuffer that still draws into the deleted storage.
TEST_F(FramebufferCacheTest, ADeletedTextureTakesItsFramebuffersWithIt) {
    FramebufferCache cache;
    const Texture kept = Texture::create2D(GL_DEPTH_COMPONENT24, 4, 4);
    cache.get({{GL_DEPTH_ATTACHMENT, kept.id()}}, "kept");
    {
        const Texture cube = Texture::createCube(GL_DEPTH_COMPONENT24, 4);
        for (int face = 0; face < 6; ++face) cache.get({{GL_DEPTH_ATTACHMENT, cube.id(), face}}, "face");
        ASSERT_EQ(cache.size(), 7u);
    }
    EXPECT_EQ(cache.size(), 1u) << "deleting the cube left framebuffers that attach it";
    const auto& framebuffer = cache.get({{GL_DEPTH_ATTACHMENT, kept.id()}}, "kept");
    EXPECT_EQ(cache.created(), 7u) << "the surviving texture's framebuffer was dropped too";
    EXPECT_FLOAT_EQ(clearAndRead(framebuffer, kept, 0.25f), 0.25f);
}
