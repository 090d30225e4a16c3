// The lit pass's light footprints (engine/scene/ScreenFootprint.h, render/ShadingRegions.h),
// computed per evaluated light and per frame on the application thread: a spot light's
// footprint over `instances` receiver boxes (a grid of boxes on the ground seen whole by the
// camera), so the cost per mesh instance shows, and the split of a 1280x720 target by
// `lights` scattered footprints.
#include "engine/render/ShadingRegions.h"
#include "engine/scene/ScreenFootprint.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

namespace {

std::vector<engine::Aabb> gridOfBoxes(int instances, int& side) {
    side = static_cast<int>(std::ceil(std::sqrt(instances)));
    std::vector<engine::Aabb> boxes;
    for (int i = 0; i < instances; ++i) {
        const glm::dvec3 corner(2.0 * (i % side) - side, 0.0, 2.0 * (i / side) - side);
        boxes.push_back({corner, corner + glm::dvec3(1.0, 1.0 + (i % 3), 1.0)});
    }
    return boxes;
}

// A spot light over a grid of `boxes` receivers seen whole by the camera: a narrow lamp over
// one corner (few boxes in its cone) or a key light whose cone holds the whole grid.
void spotFootprint(benchmark::State& state, double outerCone, bool overTheCorner) {
    int side = 0;
    const std::vector<engine::Aabb> boxes = gridOfBoxes(static_cast<int>(state.range(0)), side);
    engine::Light light;
    light.type = engine::Light::Type::Spot;
    light.outerConeAngle = outerCone;
    engine::LightInstance placed;
    const glm::dvec3 target = overTheCorner ? glm::dvec3(-side + 2.0, 0.0, -side + 2.0) : glm::dvec3(0.0);
    const glm::dvec3 eye = overTheCorner ? glm::dvec3(-side, 6.0, -side) : glm::dvec3(0.3 * side, 2.0 * side, 0.2 * side);
    placed.world = glm::inverse(glm::lookAtRH(eye, target, glm::dvec3(0.0, 0.0, 1.0)));
    const glm::dmat4 viewProjection =
        glm::perspective(0.8, 16.0 / 9.0, 0.1, 1000.0) *
        glm::lookAtRH(glm::dvec3(1.2 * side, 1.5 * side, 1.8 * side), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
    for (auto _ : state)
        benchmark::DoNotOptimize(engine::lightFootprint(light, placed, boxes, viewProjection, 1280, 720));
    state.SetItemsProcessed(state.iterations() * state.range(0));  // boxes per second
}

void BM_LampFootprint(benchmark::State& state) { spotFootprint(state, 0.5, true); }
BENCHMARK(BM_LampFootprint)->Arg(10)->Arg(100)->Arg(1000);

void BM_KeyLightFootprint(benchmark::State& state) { spotFootprint(state, 0.7, false); }
BENCHMARK(BM_KeyLightFootprint)->Arg(10)->Arg(100)->Arg(1000);

void BM_SplitByFootprints(benchmark::State& state) {
    std::vector<engine::PixelRect> footprints;
    for (int i = 0; i < state.range(0); ++i) {
        const int x = (i * 397) % 1100, y = (i * 211) % 600;
        footprints.push_back({x, y, x + 180, y + 120});
    }
    for (auto _ : state) benchmark::DoNotOptimize(engine::splitByFootprints(footprints, 1280, 720));
}
BENCHMARK(BM_SplitByFootprints)->Arg(1)->Arg(4)->Arg(8);

}  // namespace
