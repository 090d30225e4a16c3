// applyPassState sets every field of a pass's declared state, so a pass that leaves GL state
// behind (reversed Z, an offset, no depth test) cannot change how the next pass draws.
#include "GlTestContext.h"

#include "engine/graph/RenderGraph.h"
#include "engine/render/GlPassState.h"

namespace {

struct NoTextures : engine::ResourceAllocator {
    std::uint32_t acquire(const engine::TextureDesc&) override { return 0; }
    void release(std::uint32_t, const engine::TextureDesc&) override {}
};

struct ObservedState {
    GLboolean depthTest = GL_FALSE, cull = GL_FALSE, offset = GL_TRUE, clamp = GL_TRUE, srgb = GL_TRUE;
    GLint depthFunc = 0, cullFace = 0, clipDepth = 0;
    GLint viewport[4] = {};
};

ObservedState observe() {
    ObservedState state;
    state.depthTest = glIsEnabled(GL_DEPTH_TEST);
    state.cull = glIsEnabled(GL_CULL_FACE);
    state.offset = glIsEnabled(GL_POLYGON_OFFSET_FILL);
    state.clamp = glIsEnabled(GL_DEPTH_CLAMP);
    state.srgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    glGetIntegerv(GL_DEPTH_FUNC, &state.depthFunc);
    glGetIntegerv(GL_CULL_FACE_MODE, &state.cullFace);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &state.clipDepth);
    glGetIntegerv(GL_VIEWPORT, state.viewport);
    return state;
}

} // namespace

class GlPassState : public engine::test::GlTest {};

TEST_F(GlPassState, WhatAPassLeavesBehindDoesNotReachTheNext) {
    engine::RenderGraph graph;
    graph.addPass(
        "leaves_a_mess",
        [](engine::PassBuilder& builder) {
            builder.sideEffect();
            engine::PassState reversed;
            reversed.depthTest = engine::PassState::DepthTest::Greater;
            reversed.clipDepth = engine::PassState::ClipDepth::ZeroToOne;
            reversed.offsetFactor = -2.0f;
            reversed.offsetUnits = -128.0f;
            reversed.depthClamp = true;
            reversed.viewportWidth = reversed.viewportHeight = 16;
            builder.setState(reversed);
        },
        [](engine::PassContext&) {
            glDisable(GL_DEPTH_TEST);  // and changes more by hand
            glCullFace(GL_FRONT);
            glEnable(GL_FRAMEBUFFER_SRGB);
        });
    ObservedState seen;
    graph.addPass(
        "defaults",
        [](engine::PassBuilder& builder) {
            builder.sideEffect();
            engine::PassState defaults;
            defaults.viewportWidth = 8;
            defaults.viewportHeight = 4;
            builder.setState(defaults);
        },
        [&seen](engine::PassContext&) { seen = observe(); });
    engine::ExecuteOptions options;
    options.applyState = engine::applyPassState;
    NoTextures allocator;
    graph.execute(allocator, options);

    EXPECT_EQ(seen.depthTest, GL_TRUE);
    EXPECT_EQ(seen.depthFunc, GL_LESS);
    EXPECT_EQ(seen.cull, GL_TRUE);
    EXPECT_EQ(seen.cullFace, GL_BACK);
    EXPECT_EQ(seen.offset, GL_FALSE);
    EXPECT_EQ(seen.clamp, GL_FALSE);
    EXPECT_EQ(seen.srgb, GL_FALSE);
    EXPECT_EQ(seen.clipDepth, GL_NEGATIVE_ONE_TO_ONE);
    EXPECT_EQ(seen.viewport[2], 8);
    EXPECT_EQ(seen.viewport[3], 4);
}
