// Texgen setup per light and frame (shadowmap_plugin/src/math/Texgen.h): the world-space
// planes Epo = S * P_light * L^-1, the eye planes Ee = Epo * V composed directly in double,
// and the glTexGen mirror (Ee = Epo * (V^-1)^-1, with its matrix inverse) for comparison.
#include "math/Texgen.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

namespace {

// A light and a camera 10^6 units from the origin, as the precision tests use.
const glm::dvec3 kFar(1.0e6, 0.0, -2.0e6);
const glm::dmat4 kLightToWorld = glm::inverse(glm::lookAtRH(kFar + glm::dvec3(5, 20, 5), kFar, glm::dvec3(0, 0, 1)));
const glm::dmat4 kLightProjection = glm::perspective(1.2, 1.0, 0.5, 60.0);
const glm::dmat4 kEyeToWorld = glm::inverse(glm::lookAtRH(kFar + glm::dvec3(-10, 6, 12), kFar, glm::dvec3(0, 1, 0)));

void BM_ShadowTexgenPlanes(benchmark::State& state) {
    for (auto _ : state) {
        const glm::dmat4 Epo = shadowmap::shadowTexgenPlanes(kLightProjection, kLightToWorld);
        benchmark::DoNotOptimize(shadowmap::eyePlanesForCamera(Epo, kEyeToWorld));
    }
}
BENCHMARK(BM_ShadowTexgenPlanes);

void BM_TexgenMirrorSetEyePlanes(benchmark::State& state) {
    const glm::dmat4 Epo = shadowmap::shadowTexgenPlanes(kLightProjection, kLightToWorld);
    const glm::dmat4 viewMatrix = glm::inverse(kEyeToWorld);  // the modelview in effect: V^-1
    shadowmap::Texgen texgen;
    for (auto _ : state) {
        texgen.setEyePlanes(Epo, viewMatrix);
        benchmark::DoNotOptimize(texgen.eyePlanes());
    }
}
BENCHMARK(BM_TexgenMirrorSetEyePlanes);

} // namespace
