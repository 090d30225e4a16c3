#include "engine/render/GlPassState.h"

#include <epoxy/gl.h>

namespace engine {

namespace {

void setEnabled(GLenum capability, bool enabled) {
    if (enabled) glEnable(capability);
    else glDisable(capability);
}

} // namespace

void applyPassState(const PassState& state) {
    setEnabled(GL_DEPTH_TEST, state.depthTest != PassState::DepthTest::Off);
    glDepthFunc(state.depthTest == PassState::DepthTest::Greater ? GL_GREATER : GL_LESS);
    glDepthMask(state.depthWrite ? GL_TRUE : GL_FALSE);

    setEnabled(GL_CULL_FACE, state.cull != PassState::Cull::None);
    glCullFace(state.cull == PassState::Cull::Front ? GL_FRONT : GL_BACK);
    glFrontFace(GL_CCW);

    glClipControl(GL_LOWER_LEFT,
                  state.clipDepth == PassState::ClipDepth::ZeroToOne ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    setEnabled(GL_DEPTH_CLAMP, state.depthClamp);

    const bool offset = state.offsetFactor != 0.0f || state.offsetUnits != 0.0f;
    setEnabled(GL_POLYGON_OFFSET_FILL, offset);
    if (offset) glPolygonOffsetClamp(state.offsetFactor, state.offsetUnits, state.offsetClamp);

    setEnabled(GL_FRAMEBUFFER_SRGB, state.srgbWrites);
    glDisable(GL_BLEND);
    setEnabled(GL_SCISSOR_TEST, state.scissorToViewport);
    if (state.scissorToViewport) glScissor(state.viewportX, state.viewportY, state.viewportWidth, state.viewportHeight);
    glViewport(state.viewportX, state.viewportY, state.viewportWidth, state.viewportHeight);
}

} // namespace engine
