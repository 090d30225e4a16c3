// Ray-traced shadow truth (tools/truth, Embree 3): one shadow ray per covered pixel of the
// showcase at 640x360, for its first light. Reports shadow rays per second; the truth's
// correctness is tested in tools/truth/tests, its speed only read here (machines differ).
#include "truth/RayTracedVisibility.h"
#include "truth/SurfaceCapture.h"

#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/render/SceneGpu.h"

#include <benchmark/benchmark.h>

#include <cstddef>

namespace {

void BM_TruthShowcase640x360(benchmark::State& state) {
    const auto context = engine::createEglContext();
    context->makeCurrent();
    const engine::Scene scene = engine::loadGltf(MICROBENCH_SHOWCASE);
    if (scene.lightInstances.empty()) {
        state.SkipWithError("the showcase has no lights");
        return;
    }
    const engine::SceneGpu gpu(scene);
    const truth::SurfaceBuffer surfaces =
        truth::SurfaceCapture().capture(scene, gpu, engine::framingCamera(scene, 640, 360));
    const truth::RayTracedVisibility tracer(scene);
    std::size_t rays = 0;
    for (std::uint8_t covered : surfaces.covered) rays += covered;
    for (auto _ : state) benchmark::DoNotOptimize(tracer.visibility(scene, 0, surfaces));
    state.counters["rays"] = static_cast<double>(rays);
    state.counters["rays_per_second"] =
        benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TruthShowcase640x360)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
