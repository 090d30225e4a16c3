#include "GlTestContext.h"

#include "engine/gl/Sampler.h"
#include "engine/gl/Texture.h"

namespace engine::gl {
namespace {

using TextureTest = test::GlTest;

GLint textureParameter(const Texture& texture, GLenum pname) {
    GLint value = 0;
    glGetTextureParameteriv(texture.id(), pname, &value);
    return value;
}

TEST_F(TextureTest, Create2DReportsWhatItAllocated) {
    const Texture texture = Texture::create2D(GL_RGBA16F, 32, 8, 3);
    EXPECT_EQ(texture.target(), static_cast<GLenum>(GL_TEXTURE_2D));
    EXPECT_EQ(texture.internalFormat(), static_cast<GLenum>(GL_RGBA16F));
    EXPECT_EQ(texture.width(), 32);
    EXPECT_EQ(texture.height(), 8);
    EXPECT_EQ(texture.levels(), 3);
    EXPECT_EQ(textureParameter(texture, GL_TEXTURE_IMMUTABLE_LEVELS), 3);
    // Mipmapped textures keep GL's default (mipmapped) minifying filter.
    EXPECT_EQ(textureParameter(texture, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
}

TEST_F(TextureTest, SingleLevelTextureIsCompleteWithoutSetup) {
    const Texture texture = Texture::create2D(GL_DEPTH_COMPONENT24, 4, 4);
    EXPECT_EQ(textureParameter(texture, GL_TEXTURE_MIN_FILTER), GL_LINEAR);
}

TEST_F(TextureTest, CreateCubeIsSquare) {
    const Texture cube = Texture::createCube(GL_DEPTH_COMPONENT32F, 16);
    EXPECT_EQ(cube.target(), static_cast<GLenum>(GL_TEXTURE_CUBE_MAP));
    EXPECT_EQ(cube.width(), 16);
    EXPECT_EQ(cube.height(), 16);
}

TEST_F(TextureTest, ParametersReachTheTextureAndTheSampler) {
    Texture texture = Texture::create2D(GL_DEPTH_COMPONENT32F, 4, 4);
    texture.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    texture.setParameterf(GL_TEXTURE_MAX_LOD, 0.5f);
    EXPECT_EQ(textureParameter(texture, GL_TEXTURE_COMPARE_MODE), GL_COMPARE_REF_TO_TEXTURE);
    GLfloat maxLod = 0;
    glGetTextureParameterfv(texture.id(), GL_TEXTURE_MAX_LOD, &maxLod);
    EXPECT_EQ(maxLod, 0.5f);

    Sampler sampler = Sampler::create();
    sampler.set(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    sampler.setf(GL_TEXTURE_MIN_LOD, 1.0f);
    GLint compareFunc = 0;
    GLfloat minLod = 0;
    glGetSamplerParameteriv(sampler.id(), GL_TEXTURE_COMPARE_FUNC, &compareFunc);
    glGetSamplerParameterfv(sampler.id(), GL_TEXTURE_MIN_LOD, &minLod);
    EXPECT_EQ(compareFunc, GL_LEQUAL);
    EXPECT_EQ(minLod, 1.0f);
}

} // namespace
} // namespace engine::gl
