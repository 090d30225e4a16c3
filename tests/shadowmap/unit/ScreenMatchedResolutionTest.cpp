// math/ScreenMatchedResolution.h: the map side at which a texel spans at most a pixel,
// checked by stepping one texel in the light's map at each point and measuring the step on
// screen, for random lights, cameras and floor points.
#include "math/ScreenMatchedResolution.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>

namespace {

constexpr int kWidth = 1280, kHeight = 720;

// The screen distance, in pixels, of one texel of a res-sized map along the map's x and y at
// point p of a surface with normal n, the longer of the two: the ray through the map point one
// texel over, cut with the surface's plane, projected. (Geometry, not the plugin's Jacobian.)
double texelOnScreen(const glm::dmat4& light, const glm::dmat4& camera, const glm::dvec3& p, const glm::dvec3& n,
                     double res) {
    const glm::dvec4 clip = light * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    const glm::dmat4 toWorld = glm::inverse(light);
    auto unproject = [&](const glm::dvec2& xy, double z) {
        const glm::dvec4 world = toWorld * glm::dvec4(xy, z, 1.0);
        return glm::dvec3(world) / world.w;
    };
    auto pixel = [&](const glm::dvec3& world) {
        const glm::dvec4 c = camera * glm::dvec4(world, 1.0);
        return glm::dvec2(c.x / c.w * kWidth / 2.0, c.y / c.w * kHeight / 2.0);
    };
    double longest = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        glm::dvec2 stepped = ndc;
        stepped[axis] += 2.0 / res;  // one texel of NDC
        const glm::dvec3 from = unproject(stepped, -1.0), to = unproject(stepped, 1.0);
        const double t = glm::dot(p - from, n) / glm::dot(to - from, n);
        longest = std::max(longest, glm::length(pixel(from + (to - from) * t) - pixel(p)));
    }
    return longest;
}

} // namespace

TEST(ScreenMatchedResolution, ATexelOfTheMatchedMapSpansAtMostAPixelAndNearlyOne) {
    std::mt19937 random(1208);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0, coarser = 0;
    double widestRatio = 0.0;
    for (int scene = 0; scene < 200; ++scene) {
        const glm::dvec3 lamp(unit(random) * 20 - 10, 3 + unit(random) * 5, unit(random) * 20 - 10);
        const glm::dmat4 light = glm::perspective(0.4 + unit(random), 1.0, 0.5, 30.0) *
                                 glm::lookAt(lamp, lamp + glm::dvec3(unit(random) - 0.5, -1, unit(random) - 0.5),
                                             glm::dvec3(0, 0, 1));
        const glm::dvec3 eye(unit(random) * 30 - 15, 1 + unit(random) * 10, unit(random) * 30 - 15);
        const glm::dmat4 camera = glm::perspective(0.9, double(kWidth) / kHeight, 0.1, 200.0) *
                                  glm::lookAt(eye, glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
        // The floor in 2 x 2 m tiles, and some boxes standing on it.
        std::vector<engine::Aabb> receivers;
        for (int tile = 0; tile < 400; ++tile) {
            const glm::dvec3 corner(-20.0 + 2.0 * (tile % 20), -0.1, -20.0 + 2.0 * (tile / 20));
            receivers.push_back({corner, corner + glm::dvec3(2.0, 0.1, 2.0)});
            if (tile % 37 == 0) receivers.push_back({corner + glm::dvec3(0.5, 0.1, 0.5), corner + glm::dvec3(1.5, 1.2, 1.5)});
        }
        const std::vector<shadowmap::ReceiverSample> points = shadowmap::receiverSamples(light, receivers);
        const double res = shadowmap::screenMatchedResolution(light, camera, kWidth, kHeight, points);
        if (res <= 0.0) continue;
        // Every point of a receiver's surface facing the light that the light reaches and the
        // camera sees, not only the samples the size was taken from: random points on each
        // box's top (the light is above them all), kept where both views hold them.
        for (const engine::Aabb& receiver : receivers) {
            for (int i = 0; i < 40; ++i) {
                const glm::dvec3 p(receiver.min.x + (receiver.max.x - receiver.min.x) * unit(random), receiver.max.y,
                                   receiver.min.z + (receiver.max.z - receiver.min.z) * unit(random));
                const glm::dvec4 l = light * glm::dvec4(p, 1.0), c = camera * glm::dvec4(p, 1.0);
                if (l.w <= 0 || std::abs(l.x) > l.w || std::abs(l.y) > l.w || c.w <= 0 || std::abs(c.x) > c.w ||
                    std::abs(c.y) > c.w || std::abs(c.z) > c.w)
                    continue;
                ++checked;
                widestRatio = std::max(widestRatio, texelOnScreen(light, camera, p, glm::dvec3(0, 1, 0), res));
            }
        }
        // And the size is not needlessly fine: at the sample the size was taken from (in the
        // light's frustum, in front of the camera, on screen or beside it), a texel spans a
        // pixel over the margin (0.8), to rounding.
        double widest = 0.0;
        for (const shadowmap::ReceiverSample& sample : points) {
            const glm::dvec4 l = light * glm::dvec4(sample.point, 1.0), c = camera * glm::dvec4(sample.point, 1.0);
            if (l.w > 0 && std::abs(l.x) <= l.w && std::abs(l.y) <= l.w && c.w > 0 && std::abs(c.z) <= c.w)
                widest = std::max(widest, texelOnScreen(light, camera, sample.point, sample.normal, res));
        }
        coarser += widest * shadowmap::kMatchedSampleMargin >= 0.99;
    }
    std::printf("widest texel at the matched size: %.6f pixels\n", widestRatio);
    // kMatchedSampleMargin covers the texels between samples (measured without it: 1.16), and
    // a whole texel against the derivative over 1e-4 of NDC differs by perspective's
    // second-order change across one texel (measured: 0.13 % at most): 1 % allowed for that.
    EXPECT_LE(widestRatio, 1.01);
    EXPECT_GT(checked, 1000);
    EXPECT_GT(coarser, 50) << "the matched size is far finer than a pixel needs";
}
