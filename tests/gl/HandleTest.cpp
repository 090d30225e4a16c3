// Ownership rules shared by every GL owner (Handle.h): move, release, wrap, destroy.
#include "GlTestContext.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Framebuffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/Sampler.h"
#include "engine/gl/Texture.h"
#include "engine/gl/VertexArray.h"

#include <functional>

namespace engine::gl {
namespace {

using HandleTest = test::GlTest;

// Creates an owner, checks GL knows its name, lets it die, checks the name is gone.
template <typename Owner>
void expectDeletedWithOwner(const std::function<Owner()>& create,
                            const std::function<GLboolean(GLuint)>& exists) {
    GLuint name = 0;
    {
        const Owner owner = create();
        name = owner.id();
        ASSERT_NE(name, 0u);
        EXPECT_TRUE(exists(name));
    }
    EXPECT_FALSE(exists(name));
}

TEST_F(HandleTest, EveryOwnerDeletesItsNameWhenItDies) {
    expectDeletedWithOwner<Buffer>([] { return Buffer::create(4, nullptr); },
                                   [](GLuint n) { return glIsBuffer(n); });
    expectDeletedWithOwner<Texture>([] { return Texture::create2D(GL_RGBA8, 4, 4); },
                                    [](GLuint n) { return glIsTexture(n); });
    expectDeletedWithOwner<Sampler>(Sampler::create, [](GLuint n) { return glIsSampler(n); });
    expectDeletedWithOwner<Framebuffer>(Framebuffer::create,
                                        [](GLuint n) { return glIsFramebuffer(n); });
    expectDeletedWithOwner<VertexArray>(VertexArray::create,
                                        [](GLuint n) { return glIsVertexArray(n); });
    expectDeletedWithOwner<Program>(
        [] {
            return Program::compile("empty compute", {{GL_COMPUTE_SHADER,
                                                       "#version 450\n"
                                                       "layout(local_size_x = 1) in;\n"
                                                       "void main() {}\n"}});
        },
        [](GLuint n) { return glIsProgram(n); });
}

TEST_F(HandleTest, DefaultConstructedOwnerIsEmpty) {
    const Buffer buffer;
    EXPECT_EQ(buffer.id(), 0u);
    EXPECT_FALSE(buffer);
    EXPECT_EQ(buffer.size(), 0u);
}

TEST_F(HandleTest, MoveTransfersNameAndInfoAndEmptiesTheSource) {
    Texture source = Texture::create2D(GL_RGBA8, 8, 4);
    const GLuint name = source.id();

    Texture moved = std::move(source);
    EXPECT_EQ(moved.id(), name);
    EXPECT_EQ(moved.width(), 8);
    EXPECT_EQ(moved.height(), 4);
    EXPECT_EQ(moved.internalFormat(), static_cast<GLenum>(GL_RGBA8));
    EXPECT_EQ(source.id(), 0u);  // NOLINT(bugprone-use-after-move): the point of the test
    EXPECT_FALSE(source);
    EXPECT_EQ(source.width(), 0);
    EXPECT_EQ(source.internalFormat(), static_cast<GLenum>(GL_NONE));
    EXPECT_TRUE(glIsTexture(name));
}

TEST_F(HandleTest, MoveAssignmentDeletesTheNameItReplaces) {
    Buffer target = Buffer::create(4, nullptr);
    const GLuint replaced = target.id();
    Buffer source = Buffer::create(8, nullptr);
    const GLuint kept = source.id();

    target = std::move(source);
    EXPECT_FALSE(glIsBuffer(replaced));
    EXPECT_EQ(target.id(), kept);
    EXPECT_EQ(target.size(), 8u);
    EXPECT_EQ(source.id(), 0u); // NOLINT(bugprone-use-after-move)
}

TEST_F(HandleTest, ReleaseGivesUpOwnershipAndWrapAdoptsItBack) {
    GLuint name = 0;
    {
        Buffer buffer = Buffer::create(12, nullptr);
        name = buffer.release();
        EXPECT_EQ(buffer.id(), 0u);
        EXPECT_EQ(buffer.size(), 0u);
    }
    ASSERT_TRUE(glIsBuffer(name)); // released: nobody deleted it
    {
        const Buffer adopted = Buffer::wrap(name);
        EXPECT_EQ(adopted.id(), name);
        EXPECT_EQ(adopted.size(), 12u); // queried from GL
    }
    EXPECT_FALSE(glIsBuffer(name)); // adopted: deleted with its new owner
}

TEST_F(HandleTest, BorrowedNameSurvivesItsWrapper) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &name);
    glTextureStorage2D(name, 3, GL_DEPTH_COMPONENT24, 16, 16);
    {
        const Texture borrowed = Texture::wrap(name, Ownership::Borrow);
        EXPECT_EQ(borrowed.target(), static_cast<GLenum>(GL_TEXTURE_CUBE_MAP));
        EXPECT_EQ(borrowed.internalFormat(), static_cast<GLenum>(GL_DEPTH_COMPONENT24));
        EXPECT_EQ(borrowed.width(), 16);
        EXPECT_EQ(borrowed.height(), 16);
        EXPECT_EQ(borrowed.levels(), 3);
    }
    EXPECT_TRUE(glIsTexture(name));
    glDeleteTextures(1, &name);
}

} // namespace
} // namespace engine::gl
