#include "engine/render/GlPassTargets.h"

#include <epoxy/gl.h>

namespace engine {

void GlPassTargets::bind(const PassTargets& targets, const PassState& state, const PassContext& context) {
    if (targets.empty()) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return;
    }
    std::vector<gl::TargetAttachment> attachments;
    for (std::size_t i = 0; i < targets.colors.size(); ++i)
        attachments.push_back({static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                               context.texture(targets.colors[i].resource), targets.colors[i].layer});
    if (targets.depth.resource.valid())
        attachments.push_back({GL_DEPTH_ATTACHMENT, context.texture(targets.depth.resource), targets.depth.layer});
    const gl::Framebuffer& framebuffer = framebuffers_.get(attachments, "targets of pass \"" + context.passName() + "\"");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());

    for (std::size_t i = 0; i < targets.colors.size(); ++i)
        if (const auto& clear = targets.colors[i].clear)
            glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, static_cast<GLint>(i), clear->data());
    if (const auto& clear = targets.depth.clear) {
        if (!state.depthWrite) glDepthMask(GL_TRUE);  // the depth mask masks clears too
        glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &*clear);
        if (!state.depthWrite) glDepthMask(GL_FALSE);
    }
}

} // namespace engine
