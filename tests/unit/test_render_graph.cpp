// Render graph core without GL: a fake allocator and passes that log what happens, so
// ordering, culling, lifetimes and errors are checked as plain sequences of events.
#include "engine/graph/RenderGraph.h"
#include "graph_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <map>
#include <string>
#include <vector>

using namespace engine;
using engine::test::expectGraphError;

namespace {

const TextureDesc kColor{.width = 64, .height = 64, .format = TextureFormat::RGBA8};
const TextureDesc kDepth{.width = 256, .height = 256, .format = TextureFormat::Depth32F};

// Hands out fresh handles 1, 2, 3... (no pooling, so every acquire is visible in the log).
struct FakeAllocator : ResourceAllocator {
    std::vector<std::string>& log;
    std::uint32_t next = 1;
    explicit FakeAllocator(std::vector<std::string>& log) : log(log) {}
    std::uint32_t acquire(const TextureDesc& desc) override {
        log.push_back("acquire " + std::to_string(next) + " " + toString(desc));
        return next++;
    }
    void release(std::uint32_t handle, const TextureDesc&) override {
        log.push_back("release " + std::to_string(handle));
    }
};

const PassReport& reportOf(const RenderGraph& graph, const std::string& name) {
    for (const PassReport& report : graph.reports())
        if (report.name == name) return report;
    throw std::runtime_error("no report for " + name);
}

struct GraphTest : ::testing::Test {
    RenderGraph graph;
    std::map<std::string, ResourceHandle> made;  // transients by name, as their creators got them
    std::vector<std::string> log;
    FakeAllocator allocator{log};
    // An execute callback that logs the pass name.
    std::function<void(PassContext&)> logged(const std::string& name) {
        return [this, name](PassContext&) { log.push_back("exec " + name); };
    }
};

} // namespace

TEST_F(GraphTest, AReadSeesTheVersionItsHandleNames) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    auto shadow = graph.importTexture("shadow_map", kDepth, 101);
    graph.addPass("depth", [&](PassBuilder& b) { shadow = b.write(shadow); }, logged("depth"));
    graph.addPass("lit", [&](PassBuilder& b) { b.read(shadow); (void)b.write(target); }, logged("lit"));
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"exec depth", "exec lit"}));
    EXPECT_EQ(shadow.version, 1);
    EXPECT_EQ(reportOf(graph, "lit").reads, std::vector<ResourceHandle>{shadow});
    EXPECT_EQ(reportOf(graph, "depth").order, 0);
    EXPECT_EQ(reportOf(graph, "lit").order, 1);
}

TEST_F(GraphTest, AWriteNobodyReadsIsCulledEvenWhenItsOldVersionIsRead) {
    // "lit" reads the map as it came in (last frame's, say): the depth pass declared after it
    // makes a version nobody reads.
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    const auto shadow = graph.importTexture("shadow_map", kDepth, 101);
    graph.addPass("lit", [&](PassBuilder& b) { b.read(shadow); (void)b.write(target); }, logged("lit"));
    ResourceHandle drawn;
    graph.addPass("depth", [&](PassBuilder& b) { drawn = b.write(shadow); }, logged("depth"));
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"exec lit"}));
    EXPECT_EQ(reportOf(graph, "depth").cullReason, "no surviving pass reads 'shadow_map'");
    EXPECT_EQ(reportOf(graph, "lit").reads.at(0).version, 0);
    EXPECT_EQ(drawn.version, 1);
}

TEST_F(GraphTest, TiesKeepDeclarationOrder) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    for (const char* name : {"c", "a", "b"})
        graph.addPass(name, [&](PassBuilder& b) { made[std::string(name) + "_out"] = b.create(std::string(name) + "_out", kColor); b.sideEffect(); }, {});
    graph.addPass("final", [&](PassBuilder& b) { b.read(made.at("a_out")); (void)b.write(target); }, {});
    graph.compile();
    EXPECT_EQ(graph.executionOrder(), (std::vector<std::string>{"c", "a", "b", "final"}));
}

TEST_F(GraphTest, PassNobodyReadsIsCulledWithReasonAndNeverExecuted) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    ResourceHandle light1;
    graph.addPass("shadow_light1", [&](PassBuilder& b) { light1 = b.create("shadow_map_light1", kDepth); }, logged("shadow_light1"));
    graph.addPass("shadow_light2", [&](PassBuilder& b) { made["shadow_map_light2"] = b.create("shadow_map_light2", kDepth); }, logged("shadow_light2"));
    graph.addPass("lit", [&](PassBuilder& b) { b.read(light1); (void)b.write(target); }, logged("lit"));
    graph.addPass("idle", [](PassBuilder&) {}, logged("idle"));
    graph.execute(allocator);

    EXPECT_EQ(log, (std::vector<std::string>{"acquire 1 256x256 Depth32F", "exec shadow_light1",
                                             "exec lit", "release 1"}));
    const PassReport& culled = reportOf(graph, "shadow_light2");
    EXPECT_TRUE(culled.culled);
    EXPECT_EQ(culled.order, -1);
    EXPECT_EQ(culled.cullReason, "no surviving pass reads 'shadow_map_light2'");
    EXPECT_EQ(reportOf(graph, "idle").cullReason, "writes nothing");
    EXPECT_FALSE(reportOf(graph, "lit").culled);
    EXPECT_EQ(graph.reports().size(), 4u);  // culled passes are reported too
}

TEST_F(GraphTest, ChainWhoseEndIsCulledIsCulledEntirely) {
    graph.addPass("a", [this](PassBuilder& b) { made["a_out"] = b.create("a_out", kColor); }, logged("a"));
    graph.addPass("b", [this](PassBuilder& b) { b.read(made.at("a_out")); made["b_out"] = b.create("b_out", kColor); }, logged("b"));
    graph.addPass("c", [this](PassBuilder& b) { b.read(made.at("b_out")); made["c_out"] = b.create("c_out", kColor); }, logged("c"));
    graph.execute(allocator);
    EXPECT_TRUE(log.empty());  // nothing executed, no transient acquired
    for (const char* name : {"a", "b", "c"}) EXPECT_TRUE(reportOf(graph, name).culled) << name;
    EXPECT_EQ(reportOf(graph, "a").cullReason, "no surviving pass reads 'a_out' (culled readers: 'b')");
    EXPECT_EQ(graph.physicalSlotCount(), 0);
}

TEST_F(GraphTest, SideEffectPassSurvivesWithItsInputs) {
    graph.addPass("render", [this](PassBuilder& b) { made["color"] = b.create("color", kColor); }, logged("render"));
    graph.addPass("readback", [this](PassBuilder& b) { b.read(made.at("color")); b.sideEffect(); }, logged("readback"));
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"acquire 1 64x64 RGBA8", "exec render", "exec readback",
                                             "release 1"}));
}

TEST_F(GraphTest, WhatWouldBeACycleWithoutVersionsReadsTheOldVersion) {
    // "first" reads the history as imported, "second" writes its next version from what
    // "first" made: an order, not a cycle.
    auto history = graph.importTexture("history", kColor, 100);
    graph.addPass("first", [&](PassBuilder& b) { b.read(history); made["tmp"] = b.create("tmp", kColor); }, logged("first"));
    graph.addPass("second", [&](PassBuilder& b) { b.read(made.at("tmp")); history = b.write(history); }, logged("second"));
    graph.markOutput(history);
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"acquire 1 64x64 RGBA8", "exec first", "exec second", "release 1"}));
}

TEST_F(GraphTest, WritingTwiceFromOneVersionIsRejectedNamingBothPasses) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.addPass("one", [&](PassBuilder& b) { (void)b.write(target); }, {});
    expectGraphError([&] { graph.addPass("two", [&](PassBuilder& b) { (void)b.write(target); }, {}); },
                     {"'target' version 0", "pass 'one' already wrote version 1", "'two'"});
    // Another pass may write a transient's next version; then the creator's handle is stale.
    ResourceHandle byMaker, overwritten;
    graph.addPass("maker", [&](PassBuilder& b) { byMaker = b.create("made", kColor); }, {});
    graph.addPass("painter", [&](PassBuilder& b) { overwritten = b.write(byMaker); }, {});
    EXPECT_EQ(overwritten.version, 1);
    expectGraphError([&] { graph.addPass("late", [&](PassBuilder& b) { (void)b.write(byMaker); }, {}); },
                     {"'made' version 0", "'painter'", "'late'"});
}

TEST_F(GraphTest, ReadingAStaleVersionIsRejectedNamingBothPasses) {
    const auto shadow = graph.importTexture("shadow_map", kDepth, 101);
    graph.addPass("depth", [&](PassBuilder& b) { (void)b.write(shadow); }, {});
    expectGraphError([&] { graph.addPass("lit", [&](PassBuilder& b) { b.read(shadow); }, {}); },
                     {"pass 'lit' reads 'shadow_map' version 0", "pass 'depth' already wrote version 1"});
    // A version past the latest names nothing (a handle of a write that was rolled back).
    const ResourceHandle future{shadow.index, shadow.graph, 2};
    expectGraphError([&] { graph.addPass("lit", [&](PassBuilder& b) { b.read(future); }, {}); },
                     {"'lit'", "invalid resource handle", "version 2"});
}

TEST_F(GraphTest, DuplicateNameIsRejectedNamingBothPasses) {
    graph.addPass("first", [this](PassBuilder& b) { made["shared"] = b.create("shared", kColor); }, {});
    expectGraphError([&] { graph.addPass("second", [this](PassBuilder& b) { made["shared"] = b.create("shared", kColor); }, {}); },
                     {"'shared'", "'first'", "'second'"});
    expectGraphError([&] { graph.importTexture("shared", kColor, 1); }, {"'shared'", "'first'"});
    expectGraphError([&] { graph.addPass("first", {}, {}); }, {"'first'", "twice"});
}

TEST_F(GraphTest, InvalidHandleIsRejectedNamingThePass) {
    expectGraphError([&] { graph.addPass("lit", [](PassBuilder& b) { b.read(ResourceHandle{}); }, {}); },
                     {"'lit'", "invalid resource handle"});
    expectGraphError([&] { graph.addPass("lit", [](PassBuilder& b) { (void)b.write(ResourceHandle{7}); }, {}); },
                     {"'lit'", "invalid resource handle"});
}

TEST_F(GraphTest, AHandleOfAnotherGraphIsRejectedNamingThePass) {
    // A handle kept from an earlier frame's graph (a map's, say) names nothing in this one,
    // even where its index happens to be in range.
    RenderGraph lastFrame;
    const ResourceHandle old = lastFrame.importTexture("shadow_map_0", kDepth, 5);
    (void)graph.importTexture("target", kColor, 100);
    expectGraphError([&] { graph.addPass("lit", [&](PassBuilder& b) { b.read(old); }, {}); },
                     {"'lit'", "another graph"});
    EXPECT_EQ(graph.importedPhysical(old), 0u);
}

TEST_F(GraphTest, FailedSetupLeavesGraphUsable) {
    const auto target = graph.importTexture("target", kColor, 100);
    auto failing = [&](PassBuilder& b) {
        made["half_done"] = b.create("half_done", kColor);
        (void)b.write(target);
        b.read(ResourceHandle{});
    };
    EXPECT_THROW(graph.addPass("broken", failing, {}), GraphError);
    // The rollback freed both the name and the import's writer.
    graph.addPass("broken", [&](PassBuilder& b) { made["half_done"] = b.create("half_done", kColor); (void)b.write(target); }, {});
    graph.markOutput(target);
    graph.compile();
    EXPECT_EQ(graph.executionOrder(), (std::vector<std::string>{"broken"}));
}

TEST_F(GraphTest, ReadingOwnWriteIsRejected) {
    expectGraphError([&] {
        graph.addPass("loop", [](PassBuilder& b) { b.read(b.create("self", kColor)); }, {});
    }, {"'loop'", "'self'"});
    const auto target = graph.importTexture("target", kColor, 100);
    expectGraphError([&] {
        graph.addPass("rmw", [&](PassBuilder& b) { b.read(target); (void)b.write(target); }, {});
    }, {"'rmw'", "'target'"});
}

TEST_F(GraphTest, ImportedResourceReadWithoutWriterIsValid) {
    const auto environment = graph.importTexture("environment", kColor, 42);
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    std::uint32_t seen = 0, written = 0;
    graph.addPass("sky", [&](PassBuilder& b) { b.read(environment); (void)b.write(target); },
                  [&](PassContext& context) {
                      seen = context.texture(environment);
                      written = context.texture(target);
                      EXPECT_EQ(context.desc(environment), kColor);
                  });
    graph.execute(allocator);
    EXPECT_EQ(seen, 42u);
    EXPECT_EQ(written, 100u);
    EXPECT_TRUE(log.empty());  // imports are never acquired
    EXPECT_EQ(graph.physicalSlot(environment), -1);
}

TEST_F(GraphTest, UndeclaredTextureAccessIsRejected) {
    const auto other = graph.importTexture("other", kColor, 7);
    graph.addPass("sneaky", [](PassBuilder& b) { b.sideEffect(); },
                  [&](PassContext& context) { (void)context.texture(other); });
    expectGraphError([&] { graph.execute(allocator); }, {"'sneaky'", "'other'"});
}

// a -> b -> c in a chain: a_out dies after b, so c_out (same desc) can take its slot, while
// b_out overlaps both. A depth texture never shares with a color one.
TEST_F(GraphTest, DisjointEqualDescTransientsShareOneSlotOverlappingDoNot) {
    graph.addPass("a", [this](PassBuilder& b) { made["a_out"] = b.create("a_out", kColor); }, {});
    graph.addPass("b", [this](PassBuilder& b) { b.read(made.at("a_out")); made["b_out"] = b.create("b_out", kColor); }, {});
    graph.addPass("c", [this](PassBuilder& b) { b.read(made.at("b_out")); made["c_out"] = b.create("c_out", kColor); }, {});
    graph.addPass("d", [this](PassBuilder& b) { b.read(made.at("c_out")); made["d_depth"] = b.create("d_depth", kDepth); }, {});
    graph.addPass("e", [this](PassBuilder& b) { b.read(made.at("d_depth")); b.sideEffect(); }, {});
    graph.compile();
    const int a = graph.physicalSlot(made.at("a_out")), bb = graph.physicalSlot(made.at("b_out"));
    const int c = graph.physicalSlot(made.at("c_out")), d = graph.physicalSlot(made.at("d_depth"));
    EXPECT_EQ(a, c);
    EXPECT_NE(a, bb);
    EXPECT_NE(d, a);
    EXPECT_NE(d, bb);
    EXPECT_EQ(graph.physicalSlotCount(), 3);
}

TEST_F(GraphTest, ExecuteAcquiresBeforeFirstUserAndReleasesAfterLastUser) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    graph.addPass("shadow", [this](PassBuilder& b) { made["shadow_map"] = b.create("shadow_map", kDepth); }, logged("shadow"));
    graph.addPass("gbuffer", [this](PassBuilder& b) { made["albedo"] = b.create("albedo", kColor); }, logged("gbuffer"));
    graph.addPass("unused", [this](PassBuilder& b) { made["junk"] = b.create("junk", kColor); }, logged("unused"));
    graph.addPass("light", [this](PassBuilder& b) { b.read(made.at("shadow_map")); b.read(made.at("albedo")); made["hdr"] = b.create("hdr", kColor); }, logged("light"));
    graph.addPass("tonemap", [&](PassBuilder& b) { b.read(made.at("hdr")); (void)b.write(target); }, logged("tonemap"));
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{
                       "acquire 1 256x256 Depth32F", "exec shadow",
                       "acquire 2 64x64 RGBA8", "exec gbuffer",
                       "acquire 3 64x64 RGBA8", "exec light", "release 1", "release 2",
                       "exec tonemap", "release 3"}));
    EXPECT_TRUE(reportOf(graph, "unused").culled);
}

TEST_F(GraphTest, ThrowingPassReleasesWhatWasAcquired) {
    graph.addPass("make", [this](PassBuilder& b) { made["tmp"] = b.create("tmp", kColor); }, logged("make"));
    graph.addPass("boom", [this](PassBuilder& b) { b.read(made.at("tmp")); b.sideEffect(); },
                  [](PassContext&) { throw std::runtime_error("boom"); });
    EXPECT_THROW(graph.execute(allocator), std::runtime_error);
    EXPECT_EQ(log, (std::vector<std::string>{"acquire 1 64x64 RGBA8", "exec make", "release 1"}));
}

TEST_F(GraphTest, DrawsAndTrianglesAreCountedPerPass) {
    graph.addPass("one", [](PassBuilder& b) { b.sideEffect(); }, [](PassContext& context) {
        context.countDraw(12);
        context.countDraw(30);
    });
    graph.addPass("two", [](PassBuilder& b) { b.sideEffect(); }, [](PassContext& context) {
        context.countDraw(5);
        context.countCulledDraw();
    });
    for (int frame = 0; frame < 2; ++frame) graph.execute(allocator);  // counts are per execute
    EXPECT_EQ(reportOf(graph, "one").draws, 2u);
    EXPECT_EQ(reportOf(graph, "one").triangles, 42u);
    EXPECT_EQ(reportOf(graph, "two").draws, 1u);
    EXPECT_EQ(reportOf(graph, "two").triangles, 5u);
    EXPECT_EQ(reportOf(graph, "two").drawsCulled, 1u);
    EXPECT_EQ(reportOf(graph, "one").drawsCulled, 0u);
}

TEST_F(GraphTest, TimingCallsFinishAfterEachPass) {
    // Pass "one" takes at least 5 ms (sleep_for never returns early): its wall time must show
    // it, so a timing that measured nothing (0) fails.
    graph.addPass("one", [](PassBuilder& b) { b.sideEffect(); }, [&](PassContext& context) {
        logged("one")(context);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    });
    graph.addPass("two", [](PassBuilder& b) { b.sideEffect(); }, logged("two"));
    ExecuteOptions options{.timing = true, .finish = [&] { log.push_back("finish"); }};
    graph.execute(allocator, options);
    EXPECT_EQ(log, (std::vector<std::string>{"exec one", "finish", "exec two", "finish"}));
    EXPECT_GE(reportOf(graph, "one").wallMs, 5.0);
    log.clear();
    graph.execute(allocator, ExecuteOptions{.timing = false, .finish = options.finish});
    EXPECT_EQ(log, (std::vector<std::string>{"exec one", "exec two"}));  // no finish without timing
}

TEST_F(GraphTest, GraphvizMarksCulledPassesDashedWithReason) {
    const auto target = graph.importTexture("target", kColor, 100);
    graph.markOutput(target);
    graph.addPass("shadow_light2", [this](PassBuilder& b) { made["shadow_map_light2"] = b.create("shadow_map_light2", kDepth); }, {});
    graph.addPass("lit \"main\"", [&](PassBuilder& b) { (void)b.write(target); }, {});
    graph.compile();
    const std::string dot = graph.graphviz();
    EXPECT_EQ(dot.rfind("digraph", 0), 0u) << dot;
    const std::size_t culledLine = dot.find("shadow_light2\\nculled: no surviving pass reads 'shadow_map_light2'");
    ASSERT_NE(culledLine, std::string::npos) << dot;
    const std::size_t lineStart = dot.rfind('\n', culledLine);
    EXPECT_NE(dot.substr(lineStart, culledLine - lineStart).find("style=dashed"), std::string::npos) << dot;
    EXPECT_NE(dot.find("lit \\\"main\\\""), std::string::npos) << dot;  // quotes escaped
    EXPECT_NE(dot.find("shape=ellipse"), std::string::npos) << dot;
    EXPECT_NE(dot.find("shape=box"), std::string::npos) << dot;
}

TEST(TextureDesc, FormatsAndDescribe) {
    EXPECT_TRUE(isDepthFormat(TextureFormat::Depth24));
    EXPECT_FALSE(isDepthFormat(TextureFormat::R32F));
    EXPECT_STREQ(toString(TextureFormat::SRGB8_A8), "SRGB8_A8");
    EXPECT_EQ(toString(TextureDesc{.width = 512, .height = 512, .format = TextureFormat::Depth24, .layers = 1, .cube = true}),
              "512x512 Depth24 cube");
}
