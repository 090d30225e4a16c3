// The executor applies each pass's declared state before the pass runs, and after-pass hooks
// run after it: checked as a log of events, without GL.
#include "engine/graph/RenderGraph.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace engine;

namespace {

struct NullAllocator : ResourceAllocator {
    std::uint32_t next = 1;
    std::uint32_t acquire(const TextureDesc&) override { return next++; }
    void release(std::uint32_t, const TextureDesc&) override {}
};

std::string describe(const PassState& state) {
    return std::string(state.depthTest == PassState::DepthTest::Greater ? "greater" : "less") +
           (state.cull == PassState::Cull::Front ? " front" : state.cull == PassState::Cull::None ? " none" : " back") +
           " " + std::to_string(state.viewportWidth) + "x" + std::to_string(state.viewportHeight);
}

} // namespace

TEST(RenderGraphPassState, EachPassRunsAfterItsOwnStateWithTheViewportOfItsTarget) {
    RenderGraph graph;
    std::vector<std::string> log;
    ResourceHandle map = graph.importTexture("map", {512, 512, TextureFormat::Depth24}, 7);
    const ResourceHandle color = graph.importTexture("color", {64, 32, TextureFormat::RGBA8}, 8);
    graph.addPass(
        "depth",
        [&](PassBuilder& builder) {
            map = builder.write(map);
            PassState state;
            state.depthTest = PassState::DepthTest::Greater;
            state.cull = PassState::Cull::Front;
            builder.setState(state);
        },
        [&](PassContext&) { log.push_back("run depth"); });
    graph.addPass(
        "lit",
        [&](PassBuilder& builder) {
            builder.read(map);
            (void)builder.write(color);  // no state declared: the defaults
        },
        [&](PassContext&) { log.push_back("run lit"); });
    graph.addPass(
        "fixed_viewport",
        [&](PassBuilder& builder) {
            builder.sideEffect();
            PassState state;
            state.cull = PassState::Cull::None;
            state.viewportWidth = 3;
            state.viewportHeight = 2;
            builder.setState(state);
        },
        [&](PassContext&) { log.push_back("run fixed_viewport"); });
    graph.markOutput(color);

    ExecuteOptions options;
    options.applyState = [&](const PassState& state) { log.push_back("state " + describe(state)); };
    options.afterPass = [&](const std::string& pass) { log.push_back("after " + pass); };
    NullAllocator allocator;
    graph.execute(allocator, options);
    const std::vector<std::string> expected{
        "state greater front 512x512", "run depth",          "after depth",
        "state less back 64x32",       "run lit",            "after lit",
        "state less none 3x2",         "run fixed_viewport", "after fixed_viewport"};
    EXPECT_EQ(log, expected);
}

TEST(RenderGraphPassState, AnAfterPassHookThatThrowsStopsTheFrameThere) {
    RenderGraph graph;
    std::vector<std::string> ran;
    for (const std::string name : {"first", "second"})
        graph.addPass(name, [](PassBuilder& builder) { builder.sideEffect(); },
                      [&ran, name](PassContext&) { ran.push_back(name); });
    ExecuteOptions options;
    options.afterPass = [](const std::string& pass) {
        if (pass == "first") throw std::runtime_error("GL error at pass \"first\"");
    };
    NullAllocator allocator;
    EXPECT_THROW(graph.execute(allocator, options), std::runtime_error);
    EXPECT_EQ(ran, std::vector<std::string>{"first"});
}
