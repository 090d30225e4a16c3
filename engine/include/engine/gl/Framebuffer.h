#pragma once
// Framebuffer: an offscreen render target (glCreateFramebuffers). All our rendering, headless
// or not, goes to framebuffers we own; the window's default framebuffer is only blitted to.
#include "engine/gl/Handle.h"

#include <initializer_list>
#include <string>

namespace engine::gl {

class Texture;

namespace detail {
struct FramebufferTraits {
    static constexpr GLenum labelNamespace = GL_FRAMEBUFFER;
    static void destroy(GLuint name) noexcept { glDeleteFramebuffers(1, &name); }
};
} // namespace detail

class Framebuffer : public Handle<detail::FramebufferTraits> {
public:
    Framebuffer() = default;

    static Framebuffer create();
    static Framebuffer wrap(GLuint name, Ownership ownership = Ownership::Adopt);

    // attachment: GL_COLOR_ATTACHMENTi, GL_DEPTH_ATTACHMENT, ... A whole cube map attached
    // this way makes a layered target; use attachLayer for one face.
    void attach(GLenum attachment, const Texture& texture, int level = 0);
    // One layer of a cube map (face index 0..5, +X −X +Y −Y +Z −Z) or of an array texture.
    void attachLayer(GLenum attachment, const Texture& texture, int layer, int level = 0);

    // {GL_NONE} for a depth-only target such as a shadow map.
    void setDrawBuffers(std::initializer_list<GLenum> buffers);
    void setReadBuffer(GLenum buffer);

    // glBindFramebuffer(GL_FRAMEBUFFER, id()).
    void bind() const;

    // Throws GlError "Framebuffer '<what>' is incomplete: GL_FRAMEBUFFER_INCOMPLETE_...".
    // `what` names the target for the reader, e.g. "shadow map of light 'sun'".
    void requireComplete(const std::string& what) const;

private:
    using Handle::Handle;
};

// "GL_FRAMEBUFFER_COMPLETE", "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT", ...
std::string framebufferStatusName(GLenum status);

} // namespace engine::gl
