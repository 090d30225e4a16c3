// glTF loading (engine::loadGltf: parsing, validation, normals, closedness per mesh) of our
// showcase and of Debian's 2CylinderEngine.glb (package assimp-testmodels; skipped when absent).
#include "engine/gltf/GltfLoader.h"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

void loadRepeatedly(benchmark::State& state, const char* path) {
    if (!std::filesystem::exists(path)) {
        state.SkipWithError((std::string(path) + " not found").c_str());
        return;
    }
    std::size_t triangles = 0;
    for (auto _ : state) {
        const engine::Scene scene = engine::loadGltf(path);
        triangles = 0;
        for (const engine::Mesh& mesh : scene.meshes) triangles += mesh.triangleCount();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = static_cast<double>(triangles);
}

void BM_LoadShowcase(benchmark::State& state) { loadRepeatedly(state, MICROBENCH_SHOWCASE); }
BENCHMARK(BM_LoadShowcase)->Unit(benchmark::kMillisecond);

void BM_Load2CylinderEngine(benchmark::State& state) { loadRepeatedly(state, MICROBENCH_ENGINE_MODEL); }
BENCHMARK(BM_Load2CylinderEngine)->Unit(benchmark::kMillisecond);

} // namespace
