// Light footprints on screen (scene/ScreenFootprint.h) and the lit pass's split of its target
// by them (render/ShadingRegions.h). A footprint must hold every pixel the light can light:
// checked by sampling points of the lit volume inside a receiver box and projecting them.
#include "engine/render/ShadingRegions.h"
#include "engine/scene/ScreenFootprint.h"

#include "../support/TestScenes.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using engine::Aabb;
using engine::Light;
using engine::LightInstance;
using engine::PixelRect;

constexpr int kWidth = 320, kHeight = 180;

struct View {
    engine::FrameCamera camera = engine::test::cameraLooking({0, 9, 12}, {0, 0, 0}, kWidth, kHeight);
    glm::dmat4 viewProjection() const { return camera.projection * glm::inverse(camera.eyeToWorld); }
};

LightInstance placedLight(const glm::dvec3& position, const glm::dvec3& target) {
    LightInstance placed;
    placed.world = engine::test::placeLooking(position, target);
    return placed;
}

Light spot(double outerCone, double range = 0.0) {
    Light light;
    light.type = Light::Type::Spot;
    light.outerConeAngle = outerCone;
    light.range = range;
    return light;
}

// Whether the pixel whose centre sees `point` lies in `rect`; false for points the camera
// cannot see (behind the near plane or off the target), which no rect needs to hold.
bool visiblePixelIn(const View& view, const glm::dvec3& point, const PixelRect& rect, bool& visible) {
    const glm::dvec4 clip = view.viewProjection() * glm::dvec4(point, 1.0);
    visible = clip.w > 0.0 && clip.z >= -clip.w && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
    if (!visible) return false;
    const int x = std::min(int((clip.x / clip.w * 0.5 + 0.5) * kWidth), kWidth - 1);
    const int y = std::min(int((clip.y / clip.w * 0.5 + 0.5) * kHeight), kHeight - 1);
    return x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1;
}

// Samples `samples` points of `box` that `lit` accepts and counts the visible ones outside
// `rect`; `visibleLit` counts the visible ones (so a test can tell it sampled something).
template <typename Lit>
int visibleLitOutside(const View& view, const Aabb& box, const PixelRect& rect, Lit lit, int& visibleLit,
                      int samples = 20000) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int outside = 0;
    visibleLit = 0;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec3 point = box.min + (box.max - box.min) * glm::dvec3(unit(random), unit(random), unit(random));
        if (!lit(point)) continue;
        bool visible = false;
        const bool inside = visiblePixelIn(view, point, rect, visible);
        visibleLit += visible;
        outside += visible && !inside;
    }
    return outside;
}

TEST(ScreenFootprint, ASpotsFootprintHoldsEveryPixelItLightsAndLittleMore) {
    const View view;
    const Light light = spot(0.4);
    const LightInstance placed = placedLight({-2, 6, 1}, {-3, 0, 1});
    const std::vector<Aabb> receivers = {Aabb{{-10, -0.2, -10}, {10, 0, 10}}, Aabb{{1, 0, 1}, {2, 2, 2}}};
    const PixelRect rect = engine::lightFootprint(light, placed, receivers, view.viewProjection(), kWidth, kHeight);
    const auto inCone = [&](const glm::dvec3& point) {
        const glm::dvec3 toPoint = glm::normalize(point - placed.position());
        return glm::dot(toPoint, placed.direction()) > std::cos(light.outerConeAngle);
    };
    int visibleLit = 0;
    const Aabb underTheCone{{-7, -0.2, -4}, {1, 0, 6}};  // holds the pool of light on the floor
    EXPECT_EQ(visibleLitOutside(view, underTheCone, rect, inCone, visibleLit, 100000), 0);
    EXPECT_GT(visibleLit, 5000) << "the sampled floor under the cone is not in view: the test proves nothing";
    // The pool of light on the floor is small on screen: a rect of the whole target would
    // hold it too, but spare nothing (measured: 8.4 % of the target).
    EXPECT_LT(rect.area(), PixelRect::target(kWidth, kHeight).area() / 5);
    EXPECT_GT(rect.area(), 0);
}

TEST(ScreenFootprint, AConeAtAnAngleOverAFloorItCutsAndBoxesItHolds) {
    // A wide spot at an angle over a large floor: the pyramid around its cone, cut at the
    // floor's farthest corner, has the centre of its bounds outside it, so a face-by-face
    // test oriented by that centre found the floor outside the cone and left the floor's lit
    // pixels out of the footprint (the shade cache's image test caught it). The boxes on the
    // floor lie wholly inside the cone.
    const View view;
    const Light light = spot(0.7);
    const LightInstance placed = placedLight({5, 7, -4}, {0, 0, 0});
    const std::vector<Aabb> receivers = {Aabb{{-10, -0.2, -10}, {10, 0, 10}}, Aabb{{-1, 1, -1}, {1, 2, 1}},
                                         Aabb{{2, 0, -3}, {2.5, 3, -2.5}}};
    const PixelRect rect = engine::lightFootprint(light, placed, receivers, view.viewProjection(), kWidth, kHeight);
    const auto inCone = [&](const glm::dvec3& point) {
        return glm::dot(glm::normalize(point - placed.position()), placed.direction()) > std::cos(light.outerConeAngle);
    };
    int visibleLit = 0, allVisibleLit = 0, outside = 0;
    for (const Aabb& receiver : receivers) {
        outside += visibleLitOutside(view, receiver, rect, inCone, visibleLit, 50000);
        allVisibleLit += visibleLit;
    }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(allVisibleLit, 5000) << "the cone meets too little in view: the test proves nothing";
}

TEST(ScreenFootprint, RandomLightsBoxesAndCamerasNeverLeaveALitPixelOut) {
    // 300 seeded random scenes: 2-6 boxes of every shape, a spot (cone 0.05-1.3 rad, ranged
    // or not) or a ranged point light anywhere, a camera above or among the boxes looking at
    // one; every sampled lit point the camera sees must be inside the footprint.
    std::mt19937 random(20261203);
    std::uniform_real_distribution<double> coordinate(-8.0, 8.0), size(0.1, 6.0), unit(0.0, 1.0);
    int visibleLitTotal = 0;
    for (int scene = 0; scene < 300; ++scene) {
        std::vector<Aabb> receivers;
        const int boxes = 2 + scene % 5;
        for (int i = 0; i < boxes; ++i) {
            const glm::dvec3 corner(coordinate(random), coordinate(random) * 0.3, coordinate(random));
            receivers.push_back({corner, corner + glm::dvec3(size(random), size(random) * 0.5, size(random))});
        }
        View view;
        // Every other camera stands low among the boxes, so some reach behind it.
        const glm::dvec3 eye = scene % 2 ? glm::dvec3(coordinate(random), 0.3 + unit(random) * 2.0, coordinate(random))
                                         : glm::dvec3(coordinate(random) * 2.0, 2.0 + unit(random) * 12.0, coordinate(random) * 2.0);
        view.camera = engine::test::cameraLooking(eye, receivers[0].center(), kWidth, kHeight);
        const glm::dvec3 position(coordinate(random), unit(random) * 10.0, coordinate(random));
        const LightInstance placed = placedLight(position, receivers[scene % boxes].center());
        Light light = scene % 3 == 0 ? Light{} : spot(0.05 + 1.25 * unit(random), unit(random) < 0.5 ? 0.0 : 3.0 + 10.0 * unit(random));
        if (scene % 3 == 0) light.range = 2.0 + 8.0 * unit(random);  // Light{}: a point light
        const PixelRect rect = engine::lightFootprint(light, placed, receivers, view.viewProjection(), kWidth, kHeight);
        const auto lit = [&](const glm::dvec3& point) {
            const glm::dvec3 toPoint = point - placed.position();
            if (light.range > 0.0 && glm::length(toPoint) >= light.range) return false;
            return light.type == Light::Type::Point ||
                   glm::dot(glm::normalize(toPoint), placed.direction()) > std::cos(light.outerConeAngle);
        };
        for (const Aabb& receiver : receivers) {
            int visibleLit = 0;
            ASSERT_EQ(visibleLitOutside(view, receiver, rect, lit, visibleLit, 400), 0) << "scene " << scene;
            visibleLitTotal += visibleLit;
        }
    }
    EXPECT_GT(visibleLitTotal, 20000) << "too few lit points in view: the test proves little";
}

TEST(ScreenFootprint, RangeCutsTheConeAndThePointLightsSphere) {
    const View view;
    const std::vector<Aabb> receivers = {Aabb{{-10, -0.2, -10}, {10, 0, 10}}};
    // A cone reaching the floor only within its range: the footprint shrinks with the range.
    const LightInstance slanted = placedLight({-6, 3, 0}, {0, 0, 0});
    const PixelRect unranged = engine::lightFootprint(spot(0.3), slanted, receivers, view.viewProjection(), kWidth, kHeight);
    const PixelRect ranged = engine::lightFootprint(spot(0.3, 6.0), slanted, receivers, view.viewProjection(), kWidth, kHeight);
    EXPECT_LT(ranged.area(), unranged.area());
    int visibleLit = 0;
    const Aabb nearTheLight{{-6, -0.2, -4}, {0, 0, 4}};  // where the ranged cone meets the floor
    EXPECT_EQ(visibleLitOutside(view, nearTheLight, ranged, [&](const glm::dvec3& point) {
                  const glm::dvec3 toPoint = point - slanted.position();
                  return glm::length(toPoint) < 6.0 &&
                         glm::dot(glm::normalize(toPoint), slanted.direction()) > std::cos(0.3);
              }, visibleLit), 0);
    EXPECT_GT(visibleLit, 100);

    Light bulb;
    bulb.type = Light::Type::Point;
    bulb.range = 3.0;
    const LightInstance hanging = placedLight({3, 1, -2}, {3, 0, -2});
    const PixelRect sphere = engine::lightFootprint(bulb, hanging, receivers, view.viewProjection(), kWidth, kHeight);
    EXPECT_EQ(visibleLitOutside(view, receivers[0], sphere, [&](const glm::dvec3& point) {
                  return glm::length(point - hanging.position()) < 3.0;
              }, visibleLit), 0);
    EXPECT_GT(visibleLit, 100);
    EXPECT_LT(sphere.area(), PixelRect::target(kWidth, kHeight).area() / 4);
}

TEST(ScreenFootprint, UnboundedLightsCoverTheTargetAndNothingLitMeansEmpty) {
    const View view;
    const PixelRect target = PixelRect::target(kWidth, kHeight);
    const std::vector<Aabb> floor = {Aabb{{-10, -0.2, -10}, {10, 0, 10}}};
    const LightInstance above = placedLight({0, 5, 0}, {0, 0, 0});
    Light sun;
    sun.type = Light::Type::Directional;
    Light bulb;  // range 0: infinite
    EXPECT_EQ(engine::lightFootprint(sun, above, floor, view.viewProjection(), kWidth, kHeight), target);
    EXPECT_EQ(engine::lightFootprint(bulb, above, floor, view.viewProjection(), kWidth, kHeight), target);
    EXPECT_EQ(engine::lightFootprint(spot(1.56), above, floor, view.viewProjection(), kWidth, kHeight), target);
    // A spot facing the sky lights no receiver; nothing at all to light either.
    EXPECT_TRUE(engine::lightFootprint(spot(0.5), placedLight({0, 5, 0}, {0, 10, 0}), floor, view.viewProjection(),
                                       kWidth, kHeight).empty());
    EXPECT_TRUE(engine::lightFootprint(sun, above, {}, view.viewProjection(), kWidth, kHeight).empty());
}

TEST(ScreenFootprint, BoxesBehindTheCameraAreClippedAtTheNearPlane) {
    const View view;  // at (0, 9, 12) looking at the origin
    const glm::dmat4 viewProjection = view.viewProjection();
    EXPECT_TRUE(engine::projectedFootprint(viewProjection, Aabb{{-1, 8, 20}, {1, 10, 22}}, kWidth, kHeight).empty());
    // A floor reaching from behind the camera to the horizon: its visible part only.
    const Aabb floor{{-10, -0.2, -10}, {10, 0, 40}};
    const PixelRect rect = engine::projectedFootprint(viewProjection, floor, kWidth, kHeight);
    int visibleLit = 0;
    EXPECT_EQ(visibleLitOutside(view, floor, rect, [](const glm::dvec3&) { return true; }, visibleLit), 0);
    EXPECT_GT(visibleLit, 1000);
    EXPECT_FALSE(rect.empty());
}

// Every pixel of the target in exactly one region, and a region's set is exactly the
// footprints that hold its pixels.
void expectPartition(const std::vector<engine::ShadingRegion>& regions, const std::vector<PixelRect>& footprints,
                     int width, int height) {
    std::vector<int> cover(std::size_t(width) * height, 0);
    for (const engine::ShadingRegion& region : regions)
        for (int y = region.rect.y0; y < region.rect.y1; ++y)
            for (int x = region.rect.x0; x < region.rect.x1; ++x) {
                ++cover[std::size_t(y) * width + x];
                std::uint32_t holding = 0;
                for (std::size_t i = 0; i < footprints.size(); ++i)
                    if (footprints[i].intersects({x, y, x + 1, y + 1})) holding |= 1u << i;
                ASSERT_EQ(region.footprints, holding) << "pixel " << x << ", " << y;
            }
    for (int count : cover) ASSERT_EQ(count, 1);
}

TEST(ShadingRegions, OneFootprintSplitsTheTargetIntoFiveRegions) {
    const std::vector<PixelRect> footprints = {{10, 5, 30, 15}};
    const std::vector<engine::ShadingRegion> regions = engine::splitByFootprints(footprints, 40, 20);
    EXPECT_EQ(regions.size(), 5u);  // below, left, inside, right, above
    expectPartition(regions, footprints, 40, 20);
}

TEST(ShadingRegions, OverlappingAndClippedFootprintsPartitionTheTarget) {
    const std::vector<PixelRect> footprints = {{0, 0, 25, 12}, {15, 8, 40, 20}, {5, 2, 8, 18}, {-5, -5, 3, 50}, {}};
    const std::vector<engine::ShadingRegion> regions = engine::splitByFootprints(footprints, 40, 20);
    expectPartition(regions, footprints, 40, 20);
    // Without footprints, one region: the target.
    const std::vector<engine::ShadingRegion> whole = engine::splitByFootprints({}, 40, 20);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].rect, PixelRect::target(40, 20));
    EXPECT_EQ(whole[0].footprints, 0u);
}

TEST(ShadingRegions, RowsWithTheSameCellsMerge) {
    // Two footprints side by side of the same height: three rows, the middle one cut in four.
    const std::vector<PixelRect> footprints = {{2, 4, 8, 10}, {12, 4, 18, 10}};
    const std::vector<engine::ShadingRegion> regions = engine::splitByFootprints(footprints, 20, 14);
    EXPECT_EQ(regions.size(), 7u);  // below, 5 across the middle, above
    expectPartition(regions, footprints, 20, 14);
    EXPECT_THROW(engine::splitByFootprints(std::vector<PixelRect>(33, PixelRect{0, 0, 1, 1}), 4, 4),
                 std::invalid_argument);
}

}  // namespace
