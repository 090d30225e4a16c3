#include "engine/gl/Texture.h"

#include <cassert>

namespace engine::gl {

Texture Texture::createStorage(GLenum target, GLenum internalFormat, int width, int height,
                               int levels) {
    assert(width > 0 && height > 0 && levels > 0 && "Texture: empty size or no levels");
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    Texture texture(name, Ownership::Adopt, {target, internalFormat, width, height, levels});
    glTextureStorage2D(name, levels, internalFormat, width, height);
    // GL's default minifying filter samples mipmaps; on a single-level texture that makes
    // the texture incomplete and every fetch returns black. Shadow maps and render targets
    // are single-level, so default those to plain linear filtering.
    if (levels == 1) texture.setParameter(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    return texture;
}

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels) {
    return createStorage(GL_TEXTURE_2D, internalFormat, width, height, levels);
}

Texture Texture::createCube(GLenum internalFormat, int size, int levels) {
    return createStorage(GL_TEXTURE_CUBE_MAP, internalFormat, size, size, levels);
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers,
                               int levels) {
    assert(width > 0 && height > 0 && layers > 0 && levels > 0 && "Texture: empty array");
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &name);
    Texture texture(name, Ownership::Adopt,
                    {GL_TEXTURE_2D_ARRAY, internalFormat, width, height, levels, layers});
    glTextureStorage3D(name, levels, internalFormat, width, height, layers);
    if (levels == 1) texture.setParameter(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    return texture;
}

Texture Texture::create2DMultisample(GLenum internalFormat, int width, int height, int samples) {
    assert(width > 0 && height > 0 && samples > 1 && "Texture: empty or single-sampled multisample texture");
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &name);
    Texture texture(name, Ownership::Adopt,
                    {GL_TEXTURE_2D_MULTISAMPLE, internalFormat, width, height, 1, 1, samples});
    // Fixed locations: the colour and depth targets of one pass must sample the same points.
    glTextureStorage2DMultisample(name, samples, internalFormat, width, height, GL_TRUE);
    return texture;
}

Texture Texture::wrap(GLuint name, Ownership ownership) {
    GLint target = 0, levels = 0, internalFormat = 0, width = 0, height = 0;
    glGetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
    glGetTextureParameteriv(name, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_INTERNAL_FORMAT, &internalFormat);
    glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_HEIGHT, &height);
    // A mutable texture (glTexImage) reports 0 immutable levels; count it as one.
    if (levels == 0) levels = 1;
    return Texture(name, ownership,
                   {static_cast<GLenum>(target), static_cast<GLenum>(internalFormat), width,
                    height, levels});
}

void Texture::setParameter(GLenum pname, GLint value) {
    glTextureParameteri(id(), pname, value);
}

void Texture::setParameterf(GLenum pname, GLfloat value) {
    glTextureParameterf(id(), pname, value);
}

void Texture::bind(GLuint unit) const {
    glBindTextureUnit(unit, id());
}

} // namespace engine::gl
