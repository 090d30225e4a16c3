// The z-pass choice's test for a shadow volume that may hold the camera: sound (never "no"
// where some point of the eye or near plane lies in the volume, found by sampling) and useful
// (a caster away from the segment between camera and light is cleared).
#include "math/CameraInVolume.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using shadowmap::CameraRegion;
using shadowmap::cameraRegion;
using shadowmap::volumeMayHoldCamera;

glm::dmat4 eyeToWorldLooking(const glm::dvec3& eye, const glm::dvec3& target) {
    return glm::inverse(glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
}

// Whether the segment from q to the light (the ray toward a directional one) meets the sphere.
bool shadowRayMeetsSphere(const glm::dvec3& q, const glm::dvec4& light, const glm::dvec3& center, double radius) {
    const glm::dvec3 d = light.w == 0.0 ? glm::dvec3(light) : glm::dvec3(light) - q;
    const double upper = light.w == 0.0 ? 1e30 : 1.0;
    const double t = glm::clamp(glm::dot(center - q, d) / glm::dot(d, d), 0.0, upper);
    return glm::length(q + t * d - center) <= radius;
}

TEST(CameraInVolume, TheRegionHoldsTheEyeAndTheNearPlaneCorners) {
    const glm::dvec3 eye(3, 2, 5);
    const glm::dmat4 eyeToWorld = eyeToWorldLooking(eye, {0, 0, 0});
    const glm::dmat4 projection = glm::perspective(glm::radians(60.0), 16.0 / 9.0, 0.1, 100.0);
    const CameraRegion region = cameraRegion(eyeToWorld, projection);
    EXPECT_LE(glm::length(eye - region.center), region.radius * (1 + 1e-12));
    const glm::dmat4 clipToWorld = eyeToWorld * glm::inverse(projection);
    for (const double x : {-1.0, 1.0})
        for (const double y : {-1.0, 1.0}) {
            const glm::dvec4 p = clipToWorld * glm::dvec4(x, y, -1, 1);
            EXPECT_LE(glm::length(glm::dvec3(p) / p.w - region.center), region.radius * (1 + 1e-12));
        }
    // About the near distance, not the far: 0.1 / cos of the corner's angle.
    EXPECT_LT(region.radius, 0.2);
}

TEST(CameraInVolume, ACasterBetweenCameraAndLightMayHoldItOneAsideDoesNot) {
    const CameraRegion region = cameraRegion(eyeToWorldLooking({0, 0.5, 0}, {4, 0, 3}),
                                             glm::perspective(glm::radians(60.0), 4.0 / 3.0, 0.05, 100.0));
    const glm::dvec4 bulb(0.3, 6, 0.2, 1);
    EXPECT_TRUE(volumeMayHoldCamera(bulb, region, {0, 2, 0}, 1.7));     // a box over the camera
    EXPECT_FALSE(volumeMayHoldCamera(bulb, region, {8, 2, 8}, 1.7));    // one across the floor
    const glm::dvec4 sun(glm::normalize(glm::dvec3(-1, 2, -1)), 0);
    EXPECT_TRUE(volumeMayHoldCamera(sun, region, glm::dvec3(0, 0.5, 0) + 20.0 * glm::dvec3(sun), 1.0));
    EXPECT_FALSE(volumeMayHoldCamera(sun, region, glm::dvec3(0, 0.5, 0) - 20.0 * glm::dvec3(sun), 1.0));
    // A light beyond the caster from the camera's side: the segment stops at the light.
    EXPECT_FALSE(volumeMayHoldCamera(glm::dvec4(0, 3, 0, 1), region, {0, 9, 0}, 1.0));
}

// Random cameras, lights and casters: wherever a sampled eye or near-plane point's shadow ray
// meets the caster, the test must say "may hold"; and it clears a good share of the rest.
TEST(CameraInVolume, NeverClearsAVolumeThatHoldsASampledCameraPoint) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-10.0, 10.0), unit(0.0, 1.0);
    int held = 0, cleared = 0, trials = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::dvec3 eye(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec3 target = eye + glm::dvec3(coordinate(random), coordinate(random) * 0.3, coordinate(random));
        const double nearPlane = 0.05 + unit(random);
        const glm::dmat4 eyeToWorld = eyeToWorldLooking(eye, target);
        const glm::dmat4 projection = glm::perspective(glm::radians(30.0 + 60.0 * unit(random)), 1.5, nearPlane, 1e3);
        const CameraRegion region = cameraRegion(eyeToWorld, projection);
        const bool directional = trial % 3 == 0;
        const glm::dvec3 lightPoint(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec4 light = directional ? glm::dvec4(glm::normalize(lightPoint), 0) : glm::dvec4(lightPoint, 1);
        const glm::dvec3 caster(coordinate(random), coordinate(random), coordinate(random));
        const double radius = 0.2 + 2.0 * unit(random);
        // The eye and a grid over the near rectangle.
        const glm::dmat4 clipToWorld = eyeToWorld * glm::inverse(projection);
        std::vector<glm::dvec3> samples{eye};
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const glm::dvec4 p = clipToWorld * glm::dvec4(-1 + i / 4.0, -1 + j / 4.0, -1, 1);
                samples.push_back(glm::dvec3(p) / p.w);
            }
        bool holds = false;
        for (const glm::dvec3& q : samples) holds = holds || shadowRayMeetsSphere(q, light, caster, radius);
        const bool mayHold = volumeMayHoldCamera(light, region, caster, radius);
        ++trials;
        if (holds) {
            ++held;
            EXPECT_TRUE(mayHold) << "trial " << trial;
        }
        cleared += !mayHold;
    }
    EXPECT_GT(held, 20);             // the sampling found volumes holding the camera
    EXPECT_GT(cleared, trials / 2);  // and most random casters are cleared for z-pass
}

} // namespace
