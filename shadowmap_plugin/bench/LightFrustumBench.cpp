// Light frustum fitting (shadowmap_plugin/src/math/LightFrustum.h, CascadeFit.h), run per
// light and per frame: spot, directional and point fits over `instances` caster/receiver
// boxes (a grid of boxes on a ground plane, the light above it), so the cost per mesh
// instance shows; and for a directional light, four cascades and what `cascades: auto`
// weighs each frame (one map and 2-4 cascades fitted).
#include "math/CascadeFit.h"
#include "math/LightFrustum.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

shadowmap::ShadowBounds gridOfBoxes(int instances) {
    shadowmap::ShadowBounds bounds;
    const int side = static_cast<int>(std::ceil(std::sqrt(instances)));
    for (int i = 0; i < instances; ++i) {
        const glm::dvec3 corner(2.0 * (i % side) - side, 0.0, 2.0 * (i / side) - side);
        engine::Aabb box;
        box.extend(corner);
        box.extend(corner + glm::dvec3(1.0, 1.0 + (i % 3), 1.0));
        bounds.casters.push_back(box);
        bounds.receivers.push_back(box);
    }
    return bounds;
}

// A light high above the grid, looking at its centre (glTF lights shine down -Z).
engine::LightInstance lightAbove(const shadowmap::ShadowBounds& bounds) {
    const double height = std::sqrt(static_cast<double>(bounds.receivers.size())) * 2.0 + 10.0;
    engine::LightInstance light;
    light.world = glm::inverse(glm::lookAtRH(glm::dvec3(0.3 * height, height, 0.2 * height), glm::dvec3(0.0),
                                             glm::dvec3(0.0, 1.0, 0.0)));
    return light;
}

engine::Light lightOfType(engine::Light::Type type) {
    engine::Light light;
    light.type = type;
    light.outerConeAngle = 0.7;
    return light;
}

void BM_FitSpotLight(benchmark::State& state) {
    const auto bounds = gridOfBoxes(static_cast<int>(state.range(0)));
    const auto instance = lightAbove(bounds);
    const auto light = lightOfType(engine::Light::Type::Spot);
    for (auto _ : state) benchmark::DoNotOptimize(shadowmap::fitSpotLight(instance, light, bounds));
    state.SetItemsProcessed(state.iterations() * state.range(0));  // boxes per second
}
BENCHMARK(BM_FitSpotLight)->Arg(10)->Arg(100)->Arg(1000);

void BM_FitDirectionalLight(benchmark::State& state) {
    const auto bounds = gridOfBoxes(static_cast<int>(state.range(0)));
    const auto instance = lightAbove(bounds);
    const auto light = lightOfType(engine::Light::Type::Directional);
    for (auto _ : state) benchmark::DoNotOptimize(shadowmap::fitDirectionalLight(instance, light, bounds));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_FitDirectionalLight)->Arg(10)->Arg(100)->Arg(1000);

void BM_FitPointLight(benchmark::State& state) {
    const auto bounds = gridOfBoxes(static_cast<int>(state.range(0)));
    auto instance = lightAbove(bounds);
    instance.world[3] = glm::dvec4(0.5, 4.0, 0.5, 1.0);  // among the boxes: several faces see some
    const auto light = lightOfType(engine::Light::Type::Point);
    for (auto _ : state) benchmark::DoNotOptimize(shadowmap::fitPointLight(instance, light, bounds));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_FitPointLight)->Arg(10)->Arg(100)->Arg(1000);

// A camera over the grid's edge looking across it, as a viewer walking by would.
shadowmap::CascadeCamera cameraOver(const shadowmap::ShadowBounds& bounds) {
    const double side = std::sqrt(static_cast<double>(bounds.receivers.size())) * 2.0;
    shadowmap::CascadeCamera camera;
    camera.eyeToWorld = glm::inverse(glm::lookAtRH(glm::dvec3(0.0, 2.0, side), glm::dvec3(0.0, 0.0, 0.0),
                                                   glm::dvec3(0.0, 1.0, 0.0)));
    camera.projection = glm::perspective(0.9, 16.0 / 9.0, 0.1, 4.0 * side + 10.0);
    return camera;
}

engine::Aabb boundsOf(const shadowmap::ShadowBounds& bounds) {
    engine::Aabb all;
    for (const engine::Aabb& box : bounds.receivers) all.extend(box);
    return all;
}

void BM_FitFourStableCascades(benchmark::State& state) {
    const auto bounds = gridOfBoxes(static_cast<int>(state.range(0)));
    const auto instance = lightAbove(bounds);
    const auto light = lightOfType(engine::Light::Type::Directional);
    shadowmap::CascadeOptions options;
    options.count = 4;
    options.stable = true;
    for (auto _ : state)
        benchmark::DoNotOptimize(
            shadowmap::fitDirectionalCascades(instance, light, bounds, boundsOf(bounds), cameraOver(bounds), options));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_FitFourStableCascades)->Arg(10)->Arg(100)->Arg(1000);

void BM_AutoCascadeNeed(benchmark::State& state) {
    const auto bounds = gridOfBoxes(static_cast<int>(state.range(0)));
    const auto instance = lightAbove(bounds);
    const auto light = lightOfType(engine::Light::Type::Directional);
    shadowmap::CascadeOptions options;
    options.stable = true;
    for (auto _ : state)
        benchmark::DoNotOptimize(
            shadowmap::cascadeNeed(instance, light, bounds, boundsOf(bounds), cameraOver(bounds), options, 720));
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AutoCascadeNeed)->Arg(10)->Arg(100)->Arg(1000);

} // namespace
