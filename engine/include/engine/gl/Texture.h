#pragma once
// Texture: an immutable-storage texture (glCreateTextures + glTextureStorage2D), 2D or cube.
// Depth formats (GL_DEPTH_COMPONENT16/24/32F) work for both: shadow maps are textures.
#include "engine/gl/Handle.h"

namespace engine::gl {

// Drops every cached framebuffer that attaches `texture` (FramebufferCache.h).
void forgetTextureInFramebufferCaches(GLuint texture) noexcept;

namespace detail {
struct TextureTraits {
    static constexpr GLenum labelNamespace = GL_TEXTURE;
    // A cached framebuffer must not outlive its textures (FramebufferCache.h).
    static void destroy(GLuint name) noexcept {
        forgetTextureInFramebufferCaches(name);
        glDeleteTextures(1, &name);
    }
};
struct TextureInfo {
    GLenum target = GL_NONE;
    GLenum internalFormat = GL_NONE;
    int width = 0;
    int height = 0;
    int levels = 0;
    int layers = 1;  // array layers (2D arrays); 1 otherwise
    int samples = 1;  // samples per pixel (GL_TEXTURE_2D_MULTISAMPLE); 1 otherwise
};
} // namespace detail

class Texture : public Handle<detail::TextureTraits, detail::TextureInfo> {
public:
    Texture() = default;

    static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
    // Six square faces; as a framebuffer layer, face i is GL_TEXTURE_CUBE_MAP_POSITIVE_X + i.
    static Texture createCube(GLenum internalFormat, int size, int levels = 1);

    // A 2D array of `layers` images (e.g. a first-layer depth per cube face for depth
    // peeling, read with texelFetch on a sampler2DArray).
    static Texture create2DArray(GLenum internalFormat, int width, int height, int layers,
                                 int levels = 1);

    // A multisampled render target (GL_TEXTURE_2D_MULTISAMPLE) of `samples` per pixel, at
    // fixed sample locations: drawn into and resolved with glBlitFramebuffer, never sampled
    // with filtering (it has no sampler state).
    static Texture create2DMultisample(GLenum internalFormat, int width, int height, int samples);

    // Takes an existing texture object (it must have a target, i.e. have been bound or
    // created with glCreateTextures); target, format and size of level 0 are queried.
    static Texture wrap(GLuint name, Ownership ownership = Ownership::Adopt);

    void setParameter(GLenum pname, GLint value);
    void setParameterf(GLenum pname, GLfloat value);

    // glBindTextureUnit: binds to texture unit `unit` (the value of a sampler uniform).
    void bind(GLuint unit) const;

    GLenum target() const { return info().target; }
    GLenum internalFormat() const { return info().internalFormat; }
    int width() const { return info().width; }
    int height() const { return info().height; }
    int levels() const { return info().levels; }
    int layers() const { return info().layers; }
    int samples() const { return info().samples; }

private:
    using Handle::Handle;
    static Texture createStorage(GLenum target, GLenum internalFormat, int width, int height,
                                 int levels);
};

} // namespace engine::gl
