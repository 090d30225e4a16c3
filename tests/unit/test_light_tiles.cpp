// The clustered lit pass's tile lists (render/LightTiles.h): each pixel's tile lists every
// light whose footprint touches that tile, in ascending slot order, and no other; and,
// through the footprints, every light that reaches a point the camera sees (sampled points,
// as test_screen_footprint.cpp samples them).
#include "engine/render/Frame.h"
#include "engine/render/LightTiles.h"

#include "../support/TestScenes.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using engine::PixelRect;

// The slots whose footprint, clipped to the target, shares a pixel with the tile holding (x, y).
std::vector<std::uint32_t> expectedAt(const std::vector<PixelRect>& footprints, int x, int y, int tile, int width,
                                      int height) {
    const PixelRect cell = engine::intersection(
        {x / tile * tile, y / tile * tile, x / tile * tile + tile, y / tile * tile + tile}, PixelRect::target(width, height));
    std::vector<std::uint32_t> slots;
    for (std::size_t slot = 0; slot < footprints.size(); ++slot)
        if (engine::intersection(footprints[slot], PixelRect::target(width, height)).intersects(cell))
            slots.push_back(static_cast<std::uint32_t>(slot));
    return slots;
}

TEST(LightTiles, EveryPixelsTileListsExactlyTheFootprintsTouchingIt) {
    // A target that is not a multiple of the tile, footprints of every size, some reaching
    // past the target's edges, some empty or wholly off it.
    constexpr int kWidth = 333, kHeight = 197;
    std::mt19937 random(20261208);
    std::uniform_int_distribution<int> x(-60, kWidth + 20), y(-60, kHeight + 20), extent(0, 120);
    std::vector<PixelRect> footprints;
    for (int i = 0; i < 150; ++i) {
        const int x0 = x(random), y0 = y(random);
        footprints.push_back({x0, y0, x0 + extent(random), y0 + extent(random)});
    }
    footprints.push_back({});                             // nothing lit
    footprints.push_back(PixelRect::target(kWidth, kHeight));  // a sun
    const engine::LightTiles tiles = engine::buildLightTiles(footprints, kWidth, kHeight, engine::kLightTileSize);
    EXPECT_EQ(tiles.columns, (kWidth + 15) / 16);
    EXPECT_EQ(tiles.rows, (kHeight + 15) / 16);
    std::size_t longest = 0;
    for (int py = 0; py < kHeight; ++py)
        for (int px = 0; px < kWidth; ++px) {
            const auto listed = tiles.lightsAt(px, py);
            const std::vector<std::uint32_t> got(listed.begin(), listed.end());
            ASSERT_EQ(got, expectedAt(footprints, px, py, engine::kLightTileSize, kWidth, kHeight))
                << "pixel " << px << ", " << py;
            longest = std::max(longest, got.size());
        }
    EXPECT_GT(longest, 5u) << "footprints overlap too little to test the lists";
}

TEST(LightTiles, EveryLightReachingASeenPointIsInItsPixelsList) {
    // Random scenes of boxes and many ranged spot and point lights, a camera among them: each
    // sampled point a light reaches (inside its cone and range) and the camera sees must find
    // that light in its pixel's list.
    constexpr int kWidth = 320, kHeight = 180;
    std::mt19937 random(8122026);
    std::uniform_real_distribution<double> coordinate(-8.0, 8.0), size(0.1, 6.0), unit(0.0, 1.0);
    int checked = 0;
    for (int sceneIndex = 0; sceneIndex < 20; ++sceneIndex) {
        std::vector<engine::Aabb> receivers;
        for (int i = 0; i < 6; ++i) {
            const glm::dvec3 corner(coordinate(random), coordinate(random) * 0.3, coordinate(random));
            receivers.push_back({corner, corner + glm::dvec3(size(random), size(random) * 0.5, size(random))});
        }
        const engine::FrameCamera camera = engine::test::cameraLooking(
            {coordinate(random) * 2.0, 2.0 + unit(random) * 10.0, coordinate(random) * 2.0}, receivers[0].center(),
            kWidth, kHeight);
        const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
        std::vector<engine::Light> lights;
        std::vector<engine::LightInstance> placed;
        std::vector<PixelRect> footprints;
        for (int i = 0; i < 40; ++i) {
            engine::Light light;
            light.type = i % 3 ? engine::Light::Type::Spot : engine::Light::Type::Point;
            light.outerConeAngle = 0.1 + 0.9 * unit(random);
            light.range = 2.0 + 6.0 * unit(random);
            engine::LightInstance instance;
            const glm::dvec3 position(coordinate(random), 1.0 + unit(random) * 6.0, coordinate(random));
            instance.world = engine::test::placeLooking(position, receivers[i % receivers.size()].center());
            footprints.push_back(engine::lightFootprint(light, instance, receivers, viewProjection, kWidth, kHeight));
            lights.push_back(light);
            placed.push_back(instance);
        }
        const engine::LightTiles tiles = engine::buildLightTiles(footprints, kWidth, kHeight, engine::kLightTileSize);
        for (int sample = 0; sample < 4000; ++sample) {
            const engine::Aabb& box = receivers[sample % receivers.size()];
            const glm::dvec3 point = box.min + (box.max - box.min) * glm::dvec3(unit(random), unit(random), unit(random));
            const glm::dvec4 clip = viewProjection * glm::dvec4(point, 1.0);
            if (!(clip.w > 0.0 && clip.z >= -clip.w && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w)) continue;
            const int px = std::min(int((clip.x / clip.w * 0.5 + 0.5) * kWidth), kWidth - 1);
            const int py = std::min(int((clip.y / clip.w * 0.5 + 0.5) * kHeight), kHeight - 1);
            const auto listed = tiles.lightsAt(px, py);
            for (std::size_t slot = 0; slot < lights.size(); ++slot) {
                const glm::dvec3 toPoint = point - placed[slot].position();
                if (glm::length(toPoint) >= lights[slot].range) continue;
                if (lights[slot].type == engine::Light::Type::Spot &&
                    glm::dot(glm::normalize(toPoint), placed[slot].direction()) <= std::cos(lights[slot].outerConeAngle))
                    continue;
                ++checked;
                ASSERT_NE(std::find(listed.begin(), listed.end(), slot), listed.end())
                    << "scene " << sceneIndex << ": light " << slot << " reaches a point of pixel " << px << ", " << py
                    << " but is not in its tile's list";
            }
        }
    }
    EXPECT_GT(checked, 5000) << "too few lit points in view: the test proves little";
}

}  // namespace
