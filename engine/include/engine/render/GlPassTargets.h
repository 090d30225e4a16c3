#pragma once
// Binds a pass's declared targets (graph/PassTargets.h) on the current GL context, from
// framebuffers cached per attachment set, and clears what they ask to. A pass without
// targets gets the default framebuffer.
#include "engine/gl/FramebufferCache.h"
#include "engine/graph/RenderGraph.h"

namespace engine {

class GlPassTargets {
public:
    // After applyPassState(state): the clears honour the pass's colour encoding (sRGB
    // writes); a depth clear writes depth even in a pass that declares no depth writes.
    void bind(const PassTargets& targets, const PassState& state, const PassContext& context);

    const gl::FramebufferCache& framebuffers() const { return framebuffers_; }

private:
    gl::FramebufferCache framebuffers_;
};

} // namespace engine
