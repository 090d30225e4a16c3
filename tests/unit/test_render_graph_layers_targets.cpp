// Layer-by-layer writes of one import (a cube map drawn face by face) and the targets a pass
// declares, which the executor binds between the pass's state and the pass: checked as logs
// of events, without GL.
#include "engine/graph/RenderGraph.h"
#include "graph_test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace engine;
using engine::test::expectGraphError;

namespace {

const TextureDesc kCube{.width = 128, .height = 128, .format = TextureFormat::Depth24, .cube = true};
const TextureDesc kColor{.width = 64, .height = 32, .format = TextureFormat::RGBA8};
const TextureDesc kFace{.width = 128, .height = 128, .format = TextureFormat::Depth24};

struct CountingAllocator : ResourceAllocator {
    std::uint32_t next = 1;
    std::uint32_t acquire(const TextureDesc&) override { return next++; }
    void release(std::uint32_t, const TextureDesc&) override {}
};

std::string face(int f) { return "face" + std::to_string(f); }

struct LayersTest : ::testing::Test {
    RenderGraph graph;
    std::vector<std::string> log;
    CountingAllocator allocator;
    ResourceHandle cube = graph.importTexture("cube", kCube, 70);
    ResourceHandle color = graph.importTexture("color", kColor, 80);

    // A pass drawing `layer` of the cube into itself, logging its run; `cube` moves on to
    // the version it writes.
    void addFacePass(int layer) {
        graph.addPass(
            face(layer),
            [this, layer](PassBuilder& builder) {
                cube = builder.write(cube, layer);
                builder.setTargets(PassTargets::depthOnly(cube, layer, 1.0f));
            },
            [this, layer](PassContext&) { log.push_back("run " + face(layer)); });
    }
    void addReader() {
        graph.addPass(
            "lit",
            [this](PassBuilder& builder) {
                builder.read(cube);
                (void)builder.write(color);
            },
            [this](PassContext&) { log.push_back("run lit"); });
    }
};

} // namespace

TEST_F(LayersTest, AReaderOfTheLastFaceVersionKeepsEveryFace) {
    // Each face write keeps the other faces of the version before: the last one holds all six.
    graph.markOutput(color);
    for (int f = 0; f < 6; ++f) addFacePass(f);
    addReader();
    graph.execute(allocator);
    EXPECT_EQ(cube.version, 6);
    ASSERT_EQ(log.size(), 7u);
    EXPECT_EQ(log.back(), "run lit");
    for (int f = 0; f < 6; ++f) EXPECT_EQ(log[f], "run " + face(f));
}

TEST_F(LayersTest, AReaderDeclaredBeforeTheFacesSeesTheImportAndKeepsNoFace) {
    graph.markOutput(color);
    addReader();
    for (int f = 0; f < 6; ++f) addFacePass(f);
    graph.execute(allocator);
    EXPECT_EQ(log, std::vector<std::string>{"run lit"});
    for (int f = 0; f < 6; ++f) EXPECT_TRUE(graph.reports().at(f + 1).culled) << face(f);
}

TEST_F(LayersTest, FaceWritersNobodyReadsAreAllCulledWithTheReason) {
    for (int f = 0; f < 6; ++f) addFacePass(f);
    addReader();  // its colour target is not an output: it and then every face go
    graph.execute(allocator);
    EXPECT_TRUE(log.empty());
    for (const PassReport& report : graph.reports()) {
        EXPECT_TRUE(report.culled) << report.name;
        if (report.name != "lit") {
            EXPECT_NE(report.cullReason.find("'cube'"), std::string::npos) << report.cullReason;
        }
    }
}

TEST_F(LayersTest, AFaceWrittenFromAStaleVersionIsRejectedNamingBothPasses) {
    const ResourceHandle before = cube;
    addFacePass(3);
    expectGraphError([&] { graph.addPass("again", [&](PassBuilder& b) { (void)b.write(before, 3); }, {}); },
                     {"'again'", "'cube' version 0", "'face3' already wrote version 1"});
}

TEST_F(LayersTest, AWholeWriteDropsTheFacesBeforeItAFaceWriteKeepsTheWholeBeforeIt) {
    graph.markOutput(color);
    addFacePass(0);
    graph.addPass("whole", [&](PassBuilder& b) { cube = b.write(cube); }, [&](PassContext&) { log.push_back("run whole"); });
    addFacePass(2);
    addReader();
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"run whole", "run face2", "run lit"}));
    EXPECT_EQ(graph.reports().front().cullReason, "no surviving pass reads 'cube'");
}

TEST_F(LayersTest, PartWritesKeepTheVersionsBeforeThemAWholeWriteDropsThem) {
    // A shadow atlas: each pass renders its own rectangle, so a reader of the last version
    // needs every part written before it, back to the last whole write.
    graph.markOutput(color);
    auto addPart = [&](const std::string& name) {
        graph.addPass(name, [&](PassBuilder& b) { cube = b.writePart(cube); },
                      [this, name](PassContext&) { log.push_back("run " + name); });
    };
    addPart("early");
    graph.addPass("whole", [&](PassBuilder& b) { cube = b.write(cube); }, [&](PassContext&) { log.push_back("run whole"); });
    for (const char* name : {"a", "b", "c"}) addPart(name);
    addReader();
    graph.execute(allocator);
    EXPECT_EQ(log, (std::vector<std::string>{"run whole", "run a", "run b", "run c", "run lit"}));
    EXPECT_EQ(graph.reports().front().cullReason, "no surviving pass reads 'cube'");
}

TEST_F(LayersTest, ALayerOutsideTheTextureIsRejected) {
    expectGraphError([&] { graph.addPass("seventh", [&](PassBuilder& b) { (void)b.write(cube, 6); }, {}); },
                     {"'seventh'", "layer 6 of 'cube'", "6 layers"});
    expectGraphError([&] { graph.addPass("second", [&](PassBuilder& b) { (void)b.write(color, 1); }, {}); },
                     {"'second'", "layer 1 of 'color'", "1 layers"});
}

TEST_F(LayersTest, ATargetMustBeWrittenByThePassAndInALayerItWrites) {
    expectGraphError(
        [&] {
            graph.addPass("reads_only",
                          [&](PassBuilder& b) {
                              b.read(cube);
                              b.setTargets(PassTargets::depthOnly(cube, 0));
                          },
                          {});
        },
        {"'reads_only'", "depth target 'cube' layer 0", "not written by the pass"});
    expectGraphError(
        [&] {
            graph.addPass("wrong_face",
                          [&](PassBuilder& b) {
                              (void)b.write(cube, 1);
                              b.setTargets(PassTargets::depthOnly(cube, 2));
                          },
                          {});
        },
        {"'wrong_face'", "depth target 'cube' layer 2", "not a layer the pass writes"});
    // A failed setup leaves nothing behind: face 1 can still be written.
    addFacePass(1);
}

TEST_F(LayersTest, TargetsAreBoundAfterTheStateAndBeforeThePassWithTheirTexturesAndClears) {
    graph.markOutput(color);
    addFacePass(4);
    graph.addPass(
        "lit",
        [&](PassBuilder& b) {
            b.read(cube);
            const ResourceHandle depth = b.create("lit_depth", {64, 32, TextureFormat::Depth32F});
            (void)b.write(color);
            PassTargets targets = PassTargets::depthOnly(depth, -1, 1.0f);
            targets.colors.push_back({color, -1, std::array<float, 4>{0.5f, 0.25f, 0.0f, 1.0f}});
            b.setTargets(targets);
        },
        [&](PassContext&) { log.push_back("run lit"); });
    ExecuteOptions options;
    options.applyState = [&](const PassState& state) {
        log.push_back("state " + std::to_string(state.viewportWidth) + "x" + std::to_string(state.viewportHeight));
    };
    options.bindTargets = [&](const PassTargets& targets, const PassState&, const PassContext& context) {
        std::string bound = "targets";
        for (const ColorTarget& target : targets.colors)
            bound += " colour " + std::to_string(context.texture(target.resource)) +
                     (target.clear ? " clear " + std::to_string((*target.clear)[0]).substr(0, 4) : "");
        if (targets.depth.resource.valid())
            bound += " depth " + std::to_string(context.texture(targets.depth.resource)) + " layer " +
                     std::to_string(targets.depth.layer) +
                     (targets.depth.clear ? " clear " + std::to_string(*targets.depth.clear).substr(0, 3) : "");
        log.push_back(bound);
    };
    graph.execute(allocator, options);
    // The transient depth is the allocator's first texture (1).
    EXPECT_EQ(log, (std::vector<std::string>{"state 128x128", "targets depth 70 layer 4 clear 1.0", "run face4",
                                             "state 64x32", "targets colour 80 clear 0.50 depth 1 layer -1 clear 1.0",
                                             "run lit"}));
}

TEST_F(LayersTest, TheViewportIsTheFirstTargetsSizeNotTheFirstWrittenTexture) {
    const ResourceHandle small = graph.importTexture("small", {16, 8, TextureFormat::RGBA8}, 90);
    graph.addPass(
        "two_writes",
        [&](PassBuilder& b) {
            (void)b.write(small);  // written first, but not drawn into
            (void)b.write(color);
            b.sideEffect();
            PassTargets targets;
            targets.colors.push_back({color, -1, std::nullopt});
            b.setTargets(targets);
        },
        {});
    std::vector<std::string> viewports;
    ExecuteOptions options;
    options.applyState = [&](const PassState& state) {
        viewports.push_back(std::to_string(state.viewportWidth) + "x" + std::to_string(state.viewportHeight));
    };
    graph.execute(allocator, options);
    EXPECT_EQ(viewports, std::vector<std::string>{"64x32"});
}

// Woo on a cube map: a first-layer transient per face, each read only by its face's peel. Declared
// face by face, their lifetimes are disjoint, so the plan gives all six one physical texture.
TEST_F(LayersTest, PerFaceTransientsDeclaredFaceByFaceShareOneTexture) {
    graph.markOutput(color);
    for (int f = 0; f < 6; ++f) {
        ResourceHandle first;
        graph.addPass("first" + std::to_string(f), [&](PassBuilder& b) { first = b.create("first_layer" + std::to_string(f), kFace); },
                      {});
        graph.addPass(
            "peel" + std::to_string(f),
            [&, f](PassBuilder& b) {
                b.read(first);
                cube = b.write(cube, f);
            },
            {});
    }
    addReader();
    graph.compile();
    EXPECT_EQ(graph.physicalSlotCount(), 1);
    EXPECT_EQ(graph.executionOrder().size(), 13u);
}
