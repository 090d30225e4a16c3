// Receiver-aware caster culling (technique/UnseenShadows.h) without GL: which casters a
// view of a light's map leaves out, and when a map drawn without some casters still serves.
#include "technique/UnseenShadows.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace {

using shadowmap::castersWithUnseenShadows;

// A spot light 10 above the origin looking straight down, a 90-degree cone: its view reaches
// 10 to each side at the ground.
const glm::dmat4 kSpotView = glm::perspective(glm::radians(90.0), 1.0, 1.0, 20.0) *
                             glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0), glm::dvec3(0, 0, -1));
// Map resolution 512: one texel is 2/512 of clip space.
constexpr double kTexelNdc = 2.0 / 512.0;

engine::Scene sceneOf(const std::vector<engine::Aabb>& casters) {
    engine::Scene scene;
    for (const engine::Aabb& bounds : casters) {
        engine::MeshInstance instance;
        instance.mesh = static_cast<int>(scene.meshInstances.size());
        instance.worldBounds = bounds;
        scene.meshInstances.push_back(instance);
    }
    return scene;
}

// A tile of ground around (x, z), 1 wide, the top at y = 0.
engine::Aabb tile(double x, double z) { return {{x - 0.5, -0.1, z - 0.5}, {x + 0.5, 0.0, z + 0.5}}; }
// A unit box floating at height y over (x, z).
engine::Aabb boxAt(double x, double y, double z) { return {{x - 0.5, y, z - 0.5}, {x + 0.5, y + 1, z + 0.5}}; }

TEST(UnseenShadows, ACasterOverAVisibleReceiverStaysOneOverUnseenGroundIsLeftOut) {
    // Boxes 6 to 7 below the light at x = -6 and x = 6: their shadows fall on the ground at
    // |x| from 7.9 to 10.8 (x * 10 / depth). The camera sees only the tile at (-9, 0): the
    // first box shades it, the second shades ground nobody sees.
    const engine::Scene scene = sceneOf({boxAt(-6, 3, 0), boxAt(6, 3, 0)});
    const std::vector<engine::Aabb> seen{tile(-9, 0)};
    const std::vector<bool> unseen = castersWithUnseenShadows(kSpotView, seen, scene, kTexelNdc, false);
    EXPECT_EQ(unseen, (std::vector<bool>{false, true}));
    // The tile right under the first box lies outside its shadow: nothing is needed for it.
    const std::vector<engine::Aabb> under{tile(-6, 0)};
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, under, scene, kTexelNdc, false), (std::vector<bool>{true, true}));
}

TEST(UnseenShadows, AVisibleReceiverThatCastsIsNeverLeftOut) {
    // The box is itself a visible receiver: its shadow on itself (and its acne) stays.
    const engine::Scene scene = sceneOf({boxAt(6, 3, 0)});
    const std::vector<engine::Aabb> seen{tile(-6, 0), boxAt(6, 3, 0)};
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, seen, scene, kTexelNdc, false), (std::vector<bool>{false}));
}

TEST(UnseenShadows, ACasterWhollyBehindTheReceiverFromTheLightIsLeftOut) {
    // Seen: a shelf at height 5 over the origin. Below it (farther from the light) a box
    // whose light-space rectangle overlaps the shelf's: it cannot shade the shelf.
    engine::Aabb shelf{{-2, 5, -2}, {2, 5.2, 2}};
    const engine::Scene scene = sceneOf({boxAt(0, 1, 0), boxAt(0, 7, 0)});
    const std::vector<bool> unseen = castersWithUnseenShadows(kSpotView, {&shelf, 1}, scene, kTexelNdc, false);
    EXPECT_EQ(unseen, (std::vector<bool>{true, false}));  // below: out; above: shades the shelf
}

TEST(UnseenShadows, TheLookupsReachWidensTheReceiver) {
    // A box standing on the ground beside the seen tile: in clip space (x over depth) the
    // box starts at 1 / 10 = 0.1 (its foot, 10 below the light) and the tile ends at
    // 0.5 / 10 = 0.05. A lookup reaching 0.02 cannot read the box's texels, one reaching
    // 0.06 can.
    const engine::Scene scene = sceneOf({boxAt(1.5, 0.0, 0)});
    const std::vector<engine::Aabb> seen{tile(0, 0)};
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, seen, scene, 0.02, false), (std::vector<bool>{true}));
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, seen, scene, 0.06, false), (std::vector<bool>{false}));
}

TEST(UnseenShadows, ABoxBehindThePerspectiveLightCoversTheWholeView) {
    // Seen: a receiver straddling the light's plane, so its rectangle is unbounded: every
    // caster inside the view stays.
    const engine::Aabb straddling{{-1, 9, -1}, {1, 11, 1}};
    const engine::Scene scene = sceneOf({boxAt(6, 3, 0)});
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, {&straddling, 1}, scene, kTexelNdc, false),
              (std::vector<bool>{false}));
}

TEST(UnseenShadows, OnlyDrawnInstancesInsideTheViewAreCounted) {
    engine::Scene scene = sceneOf({boxAt(6, 3, 0), boxAt(60, 3, 0), boxAt(6, 3, 3)});
    scene.meshInstances[2].castShadows = false;  // drawn by nobody's depth pass
    const std::vector<engine::Aabb> seen{tile(-6, 0)};
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, seen, scene, kTexelNdc, false), (std::vector<bool>{true, false, false}));
    // A depth technique that draws receivers too (Woo's peel) would draw the third.
    scene.meshInstances[2].receiveShadows = true;
    EXPECT_EQ(castersWithUnseenShadows(kSpotView, seen, scene, kTexelNdc, true), (std::vector<bool>{true, false, true}));
}

TEST(UnseenShadows, AReceiverIsCutToWhatTheCameraCanSee) {
    // Looking straight down from 5 above the ground, 90-degree field, far plane 10: the
    // ground's top (y = 0) is seen within 5 of the point under the eye.
    engine::FrameCamera camera;
    camera.eyeToWorld = glm::inverse(glm::lookAt(glm::dvec3(3, 5, 0), glm::dvec3(3, 0, 0), glm::dvec3(0, 0, -1)));
    camera.projection = glm::perspective(glm::radians(90.0), 1.0, 0.1, 10.0);
    const engine::Aabb ground{{-1000, -0.1, -1000}, {1000, 0, 1000}};
    const std::vector<engine::Aabb> parts = shadowmap::visibleReceiverParts({ground}, camera);
    ASSERT_EQ(parts.size(), 1u);
    // The slab's bottom, 5.1 below the eye, is seen within 5.1 of it: to 1e-9 relative.
    EXPECT_NEAR(parts[0].min.x, 3.0 - 5.1, 1e-6);
    EXPECT_NEAR(parts[0].max.x, 3.0 + 5.1, 1e-6);
    EXPECT_NEAR(parts[0].min.z, -5.1, 1e-6);
    EXPECT_NEAR(parts[0].max.z, 5.1, 1e-6);
    EXPECT_NEAR(parts[0].min.y, -0.1, 1e-9);
    EXPECT_NEAR(parts[0].max.y, 0.0, 1e-9);
    // A small box wholly inside the frustum stays whole.
    const engine::Aabb inside{{2, 0, -1}, {4, 1, 1}};
    EXPECT_EQ(shadowmap::visibleReceiverParts({inside}, camera)[0], inside);
    // An infinite far plane leaves the box as it is.
    camera.projection = glm::infinitePerspective(glm::radians(90.0), 1.0, 0.1);
    EXPECT_EQ(shadowmap::visibleReceiverParts({ground}, camera)[0], ground);
}

// A 2D map last drawn without caster 1.
shadowmap::LightState lightDrawnWithout(std::size_t leftOut, std::size_t casters) {
    shadowmap::LightState light;
    light.frame.kind = shadowmap::MapKind::Map2D;
    light.renderedUnseen.assign(1, std::vector<bool>(casters, false));
    light.renderedUnseen[0][leftOut] = true;
    light.frame.cacheHit = true;  // as the key decided
    return light;
}

TEST(UnseenShadows, AMapDrawnWithoutACasterServesOnlyWhileItIsNotNeeded) {
    shadowmap::LightState light = lightDrawnWithout(1, 2);
    light.frame.unseenCasters = {{false, true}};  // still not needed
    shadowmap::keepCachedMapsThatHoldTheNeededCasters(light);
    EXPECT_TRUE(light.frame.cacheHit);

    light.frame.unseenCasters = {{false, false}};  // now its shadow shows
    shadowmap::keepCachedMapsThatHoldTheNeededCasters(light);
    EXPECT_FALSE(light.frame.cacheHit);

    light = lightDrawnWithout(1, 2);
    light.frame.unseenCasters.clear();  // culling off: every caster needed
    shadowmap::keepCachedMapsThatHoldTheNeededCasters(light);
    EXPECT_FALSE(light.frame.cacheHit);
}

TEST(UnseenShadows, AMapDrawnWithEveryCasterServesAnyView) {
    shadowmap::LightState light;
    light.frame.kind = shadowmap::MapKind::Map2D;
    light.renderedUnseen.assign(1, {false, false});
    light.frame.cacheHit = true;
    light.frame.unseenCasters = {{true, true}};
    shadowmap::keepCachedMapsThatHoldTheNeededCasters(light);
    EXPECT_TRUE(light.frame.cacheHit);
}

TEST(UnseenShadows, EachCascadeLayerIsJudgedOnItsOwn) {
    shadowmap::LightState light;
    light.frame.kind = shadowmap::MapKind::Cascades;
    light.renderedUnseen = {{true}, {false}};
    light.frame.cascadeHits = {true, true};
    light.frame.unseenCasters = {{false}, {false}};  // cascade 0 now needs the caster it left out
    shadowmap::keepCachedMapsThatHoldTheNeededCasters(light);
    EXPECT_EQ(light.frame.cascadeHits, (std::vector<bool>{false, true}));
    EXPECT_FALSE(light.frame.cacheHit);
}

} // namespace
