// The light planner (technique/LightPlanner.h) without a GL context: per light type which
// projection a light gets and what its views hold, why a light gets no map, what
// `cascades: auto` reuses, and when a map rendered earlier is still right.
#include "technique/LightPlanner.h"
#include "technique/Techniques.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace {

using shadowmap::LightState;
using shadowmap::MapKind;
using shadowmap::MapLayer;

constexpr int kUnit = 4, kUnits = 16;  // a texture unit for the light's map, and the GL's count

const engine::Aabb kGround{{-10, -0.1, -10}, {10, 0, 10}};
const engine::Aabb kBox{{-0.5, 0, -0.5}, {0.5, 1, 0.5}};

// A ground receiving and casting, a box on it casting, one light of `type` above them and a
// camera looking at them from the side.
struct World {
    engine::Scene scene;
    engine::FrameCamera camera;
    LightState light;

    explicit World(engine::Light::Type type) {
        addInstance(kGround);
        addInstance(kBox);
        engine::Light source;
        source.type = type;
        scene.lights.push_back(source);
        engine::LightInstance placed;
        placed.light = 0;
        const glm::dvec3 position = type == engine::Light::Type::Point ? glm::dvec3(0, 3, 0) : glm::dvec3(1, 6, 0.5);
        placed.world = shadowmap::lightToWorldFromDirection(position, glm::dvec3(-0.2, -1, -0.1));
        scene.lightInstances.push_back(placed);
        lookAt(glm::dvec3(6, 4, 8), glm::dvec3(0));
        light.name = "light";
        light.slot = 0;
        light.type = type;
    }
    void addInstance(const engine::Aabb& bounds) {
        engine::MeshInstance instance;
        instance.mesh = static_cast<int>(scene.meshInstances.size());
        instance.worldBounds = bounds;
        instance.revision = ++scene.lastInstanceRevision;
        scene.meshInstances.push_back(instance);
    }
    void lookAt(const glm::dvec3& eye, const glm::dvec3& target) {
        camera.eyeToWorld = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
        camera.projection = glm::perspective(0.9, 16.0 / 9.0, 0.1, 100.0);
        camera.width = 320;
        camera.height = 180;
    }
    // Moves the box by `offset`, as Scene::updateWorldTransforms would report it.
    void moveBox(const glm::dvec3& offset) {
        engine::MeshInstance& box = scene.meshInstances[1];
        box.world = glm::translate(box.world, offset);
        box.worldBounds = {box.worldBounds.min + offset, box.worldBounds.max + offset};
        box.revision = ++scene.lastInstanceRevision;
    }
    bool plan() { return shadowmap::planLight(light, shadowmap::planContext(scene, camera), kUnit, kUnits); }
    // Plans, expecting a map of `kind`, and returns the layers its projection renders.
    std::vector<MapLayer> plannedLayers(MapKind kind) {
        EXPECT_TRUE(plan()) << light.frame.skipReason;
        EXPECT_EQ(light.frame.kind, kind);
        return shadowmap::mapProjection(kind)->layers(light);
    }
    // Plans and decides the cache; then, as the depth passes would once they ran, records
    // what each rendered layer holds.
    void frame(bool cacheMaps = true) {
        ASSERT_TRUE(plan()) << light.frame.skipReason;
        shadowmap::decideCache(light, scene, 1, cacheMaps);
        if (light.frame.cacheHit) return;
        for (const MapLayer& layer : shadowmap::mapProjection(light.frame.kind)->layers(light))
            if (layer.keyWhenDone)
                (layer.keySlot < 0 ? light.renderedKey : light.renderedCascadeKeys[layer.keySlot]) = layer.keyWhenDone;
    }
};

TEST(LightPlanner, ASpotLightGetsOneFittedMapHoldingTheCasters) {
    World world(engine::Light::Type::Spot);
    const std::vector<MapLayer> layers = world.plannedLayers(MapKind::Map2D);
    ASSERT_EQ(layers.size(), 1u);
    EXPECT_EQ(layers[0].layer, -1);
    EXPECT_TRUE(layers[0].drawsCasters);
    // The box's top centre lies inside the map's clip volume.
    const glm::dvec4 clip = layers[0].viewProjection * glm::dvec4(0, 1, 0, 1);
    EXPECT_LT(std::abs(clip.x / clip.w), 1.0);
    EXPECT_LT(std::abs(clip.y / clip.w), 1.0);
    EXPECT_LT(std::abs(clip.z / clip.w), 1.0);
    EXPECT_TRUE(world.light.frame.warnings.empty());
}

TEST(LightPlanner, APointLightGetsSixFacesAndTheFaceFacingTheSkyDrawsNothing) {
    World world(engine::Light::Type::Point);
    const std::vector<MapLayer> faces = world.plannedLayers(MapKind::Cube);
    ASSERT_EQ(faces.size(), 6u);
    for (int face = 0; face < 6; ++face) EXPECT_EQ(faces[face].layer, face);
    // GL order +x -x +y -y +z -z: above the light (+y) is no receiver; below (-y) the ground.
    EXPECT_FALSE(faces[2].drawsCasters);
    EXPECT_TRUE(faces[3].drawsCasters);
    // Only the last face records the map's key: the map is right once every face ran.
    for (int face = 0; face < 5; ++face) EXPECT_EQ(faces[face].keyWhenDone, 0u);
}

TEST(LightPlanner, ADirectionalLightWithCascadesGetsOneLayerPerCascadeInViewDepthOrder) {
    World world(engine::Light::Type::Directional);
    world.light.settings.cascades = 3;
    EXPECT_EQ(world.plannedLayers(MapKind::Cascades).size(), 3u);
    const shadowmap::CascadeViews& cascades = world.light.frame.cascades;
    ASSERT_EQ(cascades.cascades.size(), 3u);
    ASSERT_EQ(cascades.splits.size(), 4u);
    for (int c = 0; c < 3; ++c) EXPECT_LT(cascades.splits[c], cascades.splits[c + 1]);
    EXPECT_EQ(shadowmap::mapProjection(MapKind::Cascades)->shape(world.light).layers, 3);
}

TEST(LightPlanner, AutoCascadesWeighOnceAndReuseTheAnswerWhileNothingMoves) {
    World world(engine::Light::Type::Directional);
    world.light.settings.cascades = shadowmap::kAutoCascades;
    ASSERT_TRUE(world.plan());
    EXPECT_TRUE(world.light.frame.autoCascades);
    EXPECT_FALSE(world.light.frame.cascadeNeedReused);
    const int count = world.light.frame.cascadeCount;
    EXPECT_GE(count, 1);
    EXPECT_LE(count, shadowmap::kMaxCascades);
    ASSERT_TRUE(world.plan());
    EXPECT_TRUE(world.light.frame.cascadeNeedReused);
    EXPECT_EQ(world.light.frame.cascadeCount, count);
    world.lookAt(glm::dvec3(7, 4, 8), glm::dvec3(0));  // the camera moved: weighed again
    ASSERT_TRUE(world.plan());
    EXPECT_FALSE(world.light.frame.cascadeNeedReused);
}

TEST(LightPlanner, SaysWhyALightGetsNoMap) {
    World none(engine::Light::Type::Spot);
    none.light.settings.variant = shadowmap::Variant::None;
    EXPECT_FALSE(none.plan());
    EXPECT_EQ(none.light.frame.skipReason, "variant none");
    EXPECT_EQ(none.light.frame.kind, MapKind::None);

    World dark(engine::Light::Type::Point);
    dark.scene.lights[0].intensity = 0.0f;
    EXPECT_FALSE(dark.plan());
    EXPECT_EQ(dark.light.frame.skipReason, "the light emits nothing");

    World away(engine::Light::Type::Spot);
    away.lookAt(glm::dvec3(0, 4, 30), glm::dvec3(0, 4, 60));  // nothing of the scene in view
    EXPECT_FALSE(away.plan());
    EXPECT_TRUE(away.light.frame.emptyFrustum);
    EXPECT_TRUE(away.light.frame.warnings.empty());  // nothing wrong: nothing to say

    World crowded(engine::Light::Type::Spot);
    EXPECT_FALSE(shadowmap::planLight(crowded.light, shadowmap::planContext(crowded.scene, crowded.camera), kUnits,
                                      kUnits));
    EXPECT_NE(crowded.light.frame.skipReason.find("no texture unit left"), std::string::npos);
    ASSERT_EQ(crowded.light.frame.warnings.size(), 1u);

    World degenerate(engine::Light::Type::Spot);
    degenerate.scene.lightInstances[0].world[3] = glm::dvec4(std::nan(""), 1, 0, 1);
    EXPECT_FALSE(degenerate.plan());
    EXPECT_EQ(degenerate.light.frame.skipReason.rfind("no shadow: ", 0), 0u) << degenerate.light.frame.skipReason;
    EXPECT_EQ(degenerate.light.frame.warnings.size(), 1u);
}

TEST(LightPlanner, SettingsThatDoNotApplyToTheLightTypeAreSaid) {
    World spot(engine::Light::Type::Spot);
    spot.light.settings.cascades = 2;
    ASSERT_TRUE(spot.plan());
    EXPECT_EQ(spot.light.frame.kind, MapKind::Map2D);
    ASSERT_EQ(spot.light.frame.warnings.size(), 1u);
    EXPECT_NE(spot.light.frame.warnings[0].find("cascades apply to directional lights only"), std::string::npos);

    World sun(engine::Light::Type::Directional);
    sun.light.settings.nearPlane = 0.5;
    ASSERT_TRUE(sun.plan());
    ASSERT_EQ(sun.light.frame.warnings.size(), 1u);
    EXPECT_NE(sun.light.frame.warnings[0].find("near_plane/far_plane"), std::string::npos);
}

TEST(LightPlanner, AMapIsStillRightUntilACasterInItsFrustumMoves) {
    for (const auto type : {engine::Light::Type::Spot, engine::Light::Type::Point}) {
        World world(type);
        world.frame();
        EXPECT_FALSE(world.light.frame.cacheHit);  // nothing rendered yet
        world.frame();
        EXPECT_TRUE(world.light.frame.cacheHit);
        world.moveBox({0.25, 0, 0});  // inside the frustum: the map changes
        world.frame();
        EXPECT_FALSE(world.light.frame.cacheHit);
        world.frame();
        EXPECT_TRUE(world.light.frame.cacheHit);
        world.light.settings.resolution = 1024;  // a setting of the map: rendered again
        world.frame();
        EXPECT_FALSE(world.light.frame.cacheHit);
        world.frame(false);  // caching off: never a hit
        EXPECT_FALSE(world.light.frame.cacheHit);
    }
}

TEST(LightPlanner, ChangingCasterLodDrawsTheMapAgain) {
    // The levels a pass draws follow from caster_lod with what the key already holds (the
    // views, the casters' boxes and transforms): the key must hold caster_lod itself.
    World world(engine::Light::Type::Spot);
    world.frame();
    world.frame();
    ASSERT_TRUE(world.light.frame.cacheHit);
    world.light.settings.casterLod = 1.0;
    world.frame();
    EXPECT_FALSE(world.light.frame.cacheHit);
    world.frame();
    EXPECT_TRUE(world.light.frame.cacheHit);
    world.light.settings.casterLod = 0.5;
    world.frame();
    EXPECT_FALSE(world.light.frame.cacheHit);
}

TEST(LightPlanner, ACasterOutsideTheFrustumMovesWithoutCostingTheMap) {
    World world(engine::Light::Type::Spot);
    world.addInstance({{40, 0, 40}, {41, 1, 41}});  // far outside the spot's cone
    world.frame();
    world.frame();
    ASSERT_TRUE(world.light.frame.cacheHit);
    engine::MeshInstance& far = world.scene.meshInstances.back();
    far.world = glm::translate(far.world, glm::dvec3(0, 0, 1));
    far.worldBounds = {far.worldBounds.min + glm::dvec3(0, 0, 1), far.worldBounds.max + glm::dvec3(0, 0, 1)};
    far.revision = ++world.scene.lastInstanceRevision;
    world.frame();
    EXPECT_TRUE(world.light.frame.cacheHit);
}

TEST(LightPlanner, CascadeLayersStillRightAreNotRenderedAgain) {
    World world(engine::Light::Type::Directional);
    world.light.settings.cascades = 3;
    world.frame();
    EXPECT_EQ(shadowmap::mapProjection(MapKind::Cascades)->layers(world.light).size(), 3u);
    world.frame();
    EXPECT_TRUE(world.light.frame.cacheHit);
    EXPECT_TRUE(shadowmap::mapProjection(MapKind::Cascades)->layers(world.light).empty());
    // A layer forgotten (as a new texture would be) is the only one rendered again.
    world.light.renderedCascadeKeys[1] = 0;
    world.frame();
    EXPECT_FALSE(world.light.frame.cacheHit);
    const std::vector<MapLayer> layers = shadowmap::mapProjection(MapKind::Cascades)->layers(world.light);
    ASSERT_EQ(layers.size(), 1u);
    EXPECT_EQ(layers[0].layer, 1);
    EXPECT_EQ(layers[0].keySlot, 1);
}

} // namespace
