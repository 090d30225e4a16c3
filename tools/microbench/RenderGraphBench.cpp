// Render-graph build + compile (culling, ordering, lifetime and aliasing plan) for a frame
// shaped like the engine's: per light a depth pass into an imported shadow map, a chain of
// transient post-process passes, a few debug passes nobody reads (culled), one lit pass.
// The graph is rebuilt every frame, so this is a per-frame CPU cost.
#include "engine/graph/RenderGraph.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

const engine::TextureDesc kMap{2048, 2048, engine::TextureFormat::Depth24};
const engine::TextureDesc kColor{1280, 720, engine::TextureFormat::RGBA16F};

// About `passes` passes: a quarter shadow passes, a quarter culled debug passes, the rest a
// post-process chain whose transients alternate two descs (so aliasing has work to do).
void buildFrame(engine::RenderGraph& graph, int passes) {
    const int lights = std::max(1, passes / 4), debug = std::max(1, passes / 4);
    const int post = std::max(1, passes - lights - debug - 1);
    std::vector<engine::ResourceHandle> maps;
    for (int i = 0; i < lights; ++i) {
        auto map = graph.importTexture("shadow_map_" + std::to_string(i), kMap, 1000 + i);
        graph.addPass("shadow_" + std::to_string(i), [&map](engine::PassBuilder& b) { map = b.write(map); },
                      [](engine::PassContext&) {});
        maps.push_back(map);
    }
    engine::ResourceHandle hdr;
    graph.addPass("lit", [&](engine::PassBuilder& b) {
        for (auto map : maps) b.read(map);
        hdr = b.create("hdr_0", kColor);
    }, [](engine::PassContext&) {});
    for (int i = 0; i < debug; ++i)
        graph.addPass("debug_" + std::to_string(i), [&, i](engine::PassBuilder& b) {
            b.read(maps[i % maps.size()]);
            (void)b.create("debug_view_" + std::to_string(i), kColor);
        }, [](engine::PassContext&) {});
    engine::ResourceHandle previous = hdr;
    for (int i = 1; i <= post; ++i) {
        engine::TextureDesc desc = kColor;
        if (i % 2) desc.format = engine::TextureFormat::RGBA8;
        graph.addPass("post_" + std::to_string(i), [&, i, desc](engine::PassBuilder& b) {
            b.read(previous);
            previous = b.create("hdr_" + std::to_string(i), desc);
        }, [](engine::PassContext&) {});
    }
    graph.markOutput(previous);
}

void BM_RenderGraphBuildAndCompile(benchmark::State& state) {
    const int passes = static_cast<int>(state.range(0));
    for (auto _ : state) {
        engine::RenderGraph graph;
        buildFrame(graph, passes);
        graph.compile();
        benchmark::DoNotOptimize(graph.physicalSlotCount());
    }
    state.SetItemsProcessed(state.iterations() * passes);  // passes per second
}
BENCHMARK(BM_RenderGraphBuildAndCompile)->Arg(10)->Arg(50)->Arg(200);

} // namespace
