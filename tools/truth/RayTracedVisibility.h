#pragma once
// RayTracedVisibility: the shadow ground truth of docs/metrics.md. For every
// covered pixel of a SurfaceBuffer, one shadow ray (Embree 3) from the surface point to the
// light: 1 = the light is visible there, 0 = something blocks it.
//
// Occluders are the primitives that cast shadows (node extras and KHR_lights_shadows), every
// triangle two-sided (a surface blocks light whichever way it faces). Alpha-tested casters
// (MASK materials, and BLEND by their casting policy: engine::shadowAlphaCutoff) block only
// where their alpha reaches the cutoff, sampled as the depth passes sample it
// (TextureAlpha.h), through an Embree occlusion filter.
//
// Precision: Embree works in float. Vertices are transformed to world in double and stored
// relative to the centre of the scene's bounds, so a scene 10^6 units from the origin is
// traced with the precision of one at the origin.
#include "truth/SurfaceCapture.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace engine { struct Scene; }

namespace truth {

// A light's size as the truth samples it (shadowmap settings light_radius / angular_diameter):
// spot and point lights a disk of `radius` (world units) centred on the light and facing the
// shaded point; directional lights a cone of full apex angle `angularDiameter` (radians)
// around the light's direction. Both zero: a point light (today's truth).
struct LightExtent {
    double radius = 0.0;
    double angularDiameter = 0.0;
    bool isPoint() const { return !(radius > 0.0) && !(angularDiameter > 0.0); }
};

// Shadow rays per axis of the stratified pattern over a sized light: 8x8 = 64 per covered
// pixel, in 4 packets of 16, 64 times the binary truth's rays (a 64x48 image of a penumbra
// traces in about 10 ms on two cores). Against the analytic penumbra of a straight edge
// (SoftTruthTest) a pixel is off by 0.033 on average and 0.11 at most, without bias (the mean
// of 48 pixels at one spot is within 0.016): the noise floor under a soft filter's penumbra
// error, which halves only with 4x the rays.
constexpr int kLightSamplesPerAxis = 8;

class RayTracedVisibility {
public:
    // Builds the acceleration structure of all casters of `scene` (world transforms must be
    // up to date: Scene::updateWorldTransforms). Alpha-tested casters read the scene's
    // images while tracing: `scene` must outlive this object and keep its images. Throws
    // std::runtime_error if Embree fails.
    explicit RayTracedVisibility(const engine::Scene& scene);
    ~RayTracedVisibility();
    RayTracedVisibility(RayTracedVisibility&&) noexcept;
    RayTracedVisibility& operator=(RayTracedVisibility&&) noexcept;

    // Per pixel of `surfaces`: 1 = light `lightInstance` (index into scene.lightInstances)
    // visible, 0 = occluded or pixel not covered. `scene` must hold the same casters as at
    // construction; its lights may have moved. Rays run in 16-wide packets over 4x4 pixel
    // tiles on all hardware threads. Throws std::invalid_argument for a bad light index.
    std::vector<std::uint8_t> visibility(const engine::Scene& scene, int lightInstance,
                                         const SurfaceBuffer& surfaces) const;

    // Per pixel of `surfaces`: the fraction in [0,1] of the pixel's footprint from which light
    // `lightInstance` is visible, from 4x4 stratified shadow rays per covered pixel (0 where
    // not covered). The footprint is where the camera rays through the pixel's area meet the
    // plane of the surface seen at its centre (its captured point and normal), so a pixel
    // spanning two surfaces is sampled as if its centre's surface went on. This is the truth
    // a filtered shade (PCF) approximates; a binary one is `visibility`. Throws
    // std::invalid_argument for a bad light index or a camera that does not match the pixels.
    std::vector<float> litFraction(const engine::Scene& scene, int lightInstance,
                                   const SurfaceBuffer& surfaces) const;

    // Per pixel of `surfaces`: the fraction in [0,1] of the light's extent visible from the
    // pixel's surface point (0 where not covered): the visible share of the disk's area or of
    // the cone's solid angle, unweighted by cosine or distance falloff across the source,
    // which is what a PCSS filter estimates. kLightSamplesPerAxis^2 shadow rays per covered
    // pixel, from the ray start of `visibility` to cell centres of a stratified pattern that
    // each pixel shifts by a hash of its index (Cranley-Patterson rotation, so neighbouring
    // pixels do not band alike), mapped to the light's unit disk by Shirley's concentric map:
    // to disk points (spot, point: the disk faces the ray start) or to directions uniform in
    // solid angle (directional). Only the size of the light's type applies (radius for spot
    // and point lights, angularDiameter for directional ones); 0 gives exactly `visibility`
    // as 0 or 1. Throws std::invalid_argument for a bad light index or a negative or
    // non-finite size that applies.
    std::vector<float> visibleFraction(const engine::Scene& scene, int lightInstance,
                                       const SurfaceBuffer& surfaces, const LightExtent& extent) const;

    // How far a ray origin is pushed off the surface along its normal, at world point p for a
    // capture made from cameraPosition (see the .cpp for why each term is there).
    double rayOffset(const glm::dvec3& p, const glm::dvec3& cameraPosition) const;

    std::size_t triangleCount() const { return triangles_; }
    const glm::dvec3& origin() const { return origin_; }

private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
    glm::dvec3 origin_{0.0};   // world point stored as (0,0,0) in Embree
    double sceneRadius_ = 1.0; // half the diagonal of the scene's world bounds
    std::size_t triangles_ = 0;
};

// One-shot: builds the structure, traces, frees it.
std::vector<std::uint8_t> visibility(const engine::Scene& scene, int lightInstance,
                                     const SurfaceBuffer& surfaces);

// The evaluation set E of docs/metrics.md for light `lightInstance`, per pixel (1 = in E):
// covered pixels of a shadow-receiving surface (node and primitive), inside the light's cone (spot: angle to the
// axis <= outer cone angle; point, directional: everywhere), within range (range > 0; not
// for directional lights), whose surface faces the light (geometric N.L > 0).
std::vector<std::uint8_t> evaluationSet(const engine::Scene& scene, int lightInstance,
                                        const SurfaceBuffer& surfaces);

} // namespace truth
