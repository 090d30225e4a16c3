// The executor binds each pass's declared targets (GlPassTargets): the right texture and
// layer, the declared clears (also where the pass writes no depth), the default framebuffer
// for a pass without targets whatever the pass before it left bound, and one framebuffer per
// target set across frames.
#include "GlTestContext.h"

#include "engine/graph/RenderGraph.h"
#include "engine/render/GlPassState.h"
#include "engine/render/GlPassTargets.h"
#include "engine/render/TextureReadback.h"

namespace {

struct NoTransients : engine::ResourceAllocator {
    std::uint32_t acquire(const engine::TextureDesc&) override { return 0; }
    void release(std::uint32_t, const engine::TextureDesc&) override {}
};

constexpr int kSize = 4;
const engine::TextureDesc kCubeDesc{kSize, kSize, engine::TextureFormat::Depth32F, 1, true};

// Runs `graph` the way the renderer does: state, then targets, then the pass.
void execute(engine::RenderGraph& graph, engine::GlPassTargets& targets) {
    engine::ExecuteOptions options;
    options.applyState = engine::applyPassState;
    options.bindTargets = [&targets](const engine::PassTargets& declared, const engine::PassState& state,
                                     const engine::PassContext& context) { targets.bind(declared, state, context); };
    NoTransients allocator;
    graph.execute(allocator, options);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// A graph whose six passes each clear one face of `cube` to (face + 1) / 8, the odd faces
// in passes that declare no depth writes.
void addFaceClears(engine::RenderGraph& graph, const engine::gl::Texture& cube) {
    engine::ResourceHandle map = graph.importTexture("cube", kCubeDesc, cube.id());
    for (int face = 0; face < 6; ++face)
        graph.addPass(
            "face" + std::to_string(face),
            [&map, face](engine::PassBuilder& builder) {  // setup runs inside addPass
                map = builder.write(map, face);
                builder.sideEffect();
                builder.setTargets(engine::PassTargets::depthOnly(map, face, (face + 1) / 8.0f));
                engine::PassState state;
                state.depthWrite = face % 2 == 0;
                builder.setState(state);
            },
            {});
}

} // namespace

class GlPassTargets : public engine::test::GlTest {
protected:
    // The passes here leave their state behind (the renderer resets it after each frame):
    // later tests on this context start from the defaults.
    void TearDown() override {
        engine::PassState defaults;
        defaults.viewportWidth = defaults.viewportHeight = 64;
        engine::applyPassState(defaults);
        GlTest::TearDown();
    }
};

TEST_F(GlPassTargets, EachFacePassClearsItsOwnFaceEvenWithoutDepthWrites) {
    const engine::gl::Texture cube = engine::gl::Texture::createCube(GL_DEPTH_COMPONENT32F, kSize);
    engine::RenderGraph graph;
    addFaceClears(graph, cube);
    engine::GlPassTargets targets;
    execute(graph, targets);

    const std::vector<float> depth = engine::readDepthLayersTopDown(cube.id(), kSize, kSize, 6);
    for (int face = 0; face < 6; ++face)
        for (int texel = 0; texel < kSize * kSize; ++texel)
            ASSERT_EQ(depth[face * kSize * kSize + texel], (face + 1) / 8.0f) << "face " << face;
    // The depth mask the odd faces' passes declared is what they left behind.
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    EXPECT_EQ(mask, GL_FALSE);
}

TEST_F(GlPassTargets, APassDrawsIntoItsTargetAndAPassWithoutTargetsIntoTheDefaultFramebuffer) {
    const engine::gl::Texture cube = engine::gl::Texture::createCube(GL_DEPTH_COMPONENT32F, kSize);
    const engine::gl::Texture stray = engine::gl::Texture::create2D(GL_RGBA8, kSize, kSize);
    engine::gl::Framebuffer leftBound = engine::gl::Framebuffer::create();
    glNamedFramebufferTexture(leftBound.id(), GL_COLOR_ATTACHMENT0, stray.id(), 0);

    engine::RenderGraph graph;
    const engine::ResourceHandle map = graph.importTexture("cube", kCubeDesc, cube.id());
    GLint attachedTexture = 0, attachedFace = 0, boundAfterMess = -1;
    graph.addPass(
        "face5",
        [map](engine::PassBuilder& builder) {
            (void)builder.write(map, 5);
            builder.sideEffect();
            builder.setTargets(engine::PassTargets::depthOnly(map, 5));
        },
        [&](engine::PassContext&) {
            glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attachedTexture);
            // A cube map's layer is reported as the face it selects.
            glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                  GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &attachedFace);
            glBindFramebuffer(GL_FRAMEBUFFER, leftBound.id());  // and leaves its own bound
        });
    graph.addPass(
        "no_targets", [](engine::PassBuilder& builder) { builder.sideEffect(); },
        [&](engine::PassContext&) { glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &boundAfterMess); });
    engine::GlPassTargets targets;
    execute(graph, targets);

    EXPECT_EQ(static_cast<GLuint>(attachedTexture), cube.id());
    EXPECT_EQ(attachedFace, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z);
    EXPECT_EQ(boundAfterMess, 0);
}

TEST_F(GlPassTargets, AColourClearIsEncodedLikeThePassesWrites) {
    const engine::gl::Texture srgb = engine::gl::Texture::create2D(GL_SRGB8_ALPHA8, kSize, kSize);
    engine::RenderGraph graph;
    const engine::ResourceHandle target =
        graph.importTexture("srgb", {kSize, kSize, engine::TextureFormat::SRGB8_A8}, srgb.id());
    graph.addPass(
        "clear",
        [target](engine::PassBuilder& builder) {
            (void)builder.write(target);
            builder.sideEffect();
            engine::PassTargets targets;
            targets.colors.push_back({target, -1, std::array<float, 4>{0.5f, 0.0f, 1.0f, 1.0f}});
            builder.setTargets(targets);
            engine::PassState state;
            state.srgbWrites = true;
            builder.setState(state);
        },
        {});
    engine::GlPassTargets targets;
    execute(graph, targets);
    const std::vector<std::uint8_t> rgba = engine::readTextureRGBA8TopDown(srgb);
    // Linear 0.5 encodes to sRGB 0.7354 (IEC 61966-2-1): 187.5, stored as 187 or 188. Unencoded
    // it would read back 128 (0.5 * 255 rounded).
    EXPECT_NEAR(rgba[0], 187.5, 0.5);
    EXPECT_EQ(rgba[2], 255);
}

TEST_F(GlPassTargets, TheSameTargetsReuseOneFramebufferFrameAfterFrame) {
    const engine::gl::Texture cube = engine::gl::Texture::createCube(GL_DEPTH_COMPONENT32F, kSize);
    engine::GlPassTargets targets;
    for (int frame = 0; frame < 3; ++frame) {
        engine::RenderGraph graph;
        addFaceClears(graph, cube);
        execute(graph, targets);
    }
    EXPECT_EQ(targets.framebuffers().created(), 6u);  // one per face, made in the first frame
}
