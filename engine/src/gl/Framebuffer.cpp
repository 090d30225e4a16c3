#include "engine/gl/Framebuffer.h"

#include "engine/gl/GlError.h"
#include "engine/gl/Texture.h"

#include <vector>

namespace engine::gl {

Framebuffer Framebuffer::create() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return Framebuffer(name, Ownership::Adopt, {});
}

Framebuffer Framebuffer::wrap(GLuint name, Ownership ownership) {
    return Framebuffer(name, ownership, {});
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level) {
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attachLayer(GLenum attachment, const Texture& texture, int layer, int level) {
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(std::initializer_list<GLenum> buffers) {
    const std::vector<GLenum> list(buffers);
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(list.size()), list.data());
}

void Framebuffer::setReadBuffer(GLenum buffer) {
    glNamedFramebufferReadBuffer(id(), buffer);
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
}

void Framebuffer::requireComplete(const std::string& what) const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("Framebuffer '" + what + "' is incomplete: " +
                      framebufferStatusName(status));
}

std::string framebufferStatusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
        return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    case 0: // glCheckNamedFramebufferStatus itself failed
        return "status check failed (" + glErrorName(glGetError()) + ")";
    default: return hexEnum(status);
    }
}

} // namespace engine::gl
