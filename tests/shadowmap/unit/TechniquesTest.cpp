// The technique registry (technique/Techniques.h) and the depth techniques' passes, checked on
// the render graph without GL: every choice the settings accept has its technique, and each
// way of making a map declares, runs and draws the passes it says it does.
#include "technique/Techniques.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <string>
#include <vector>

namespace {

using shadowmap::DepthTechnique;
using shadowmap::LightState;
using shadowmap::MapKind;
using shadowmap::MapLayer;

// Every value the settings API accepts for `key`, parsed.
std::vector<shadowmap::ShadowSettings> everyChoiceOf(const std::string& key) {
    std::vector<shadowmap::ShadowSettings> settings;
    for (const std::string& choice : shadowmap::settingKey(key).choices)
        settings.push_back(shadowmap::parseSettings({{key, choice}}, "test", "defaults"));
    return settings;
}

TEST(Techniques, EveryVariantWithAMapHasTheDepthTechniqueOfItsName) {
    for (const shadowmap::ShadowSettings& settings : everyChoiceOf("variant")) {
        const DepthTechnique* technique = shadowmap::depthTechnique(settings.variant);
        if (!shadowmap::usesDepthMap(settings.variant)) {
            EXPECT_EQ(technique, nullptr);
            continue;
        }
        ASSERT_NE(technique, nullptr) << toString(settings.variant);
        EXPECT_EQ(technique->variant(), settings.variant);
    }
}

TEST(Techniques, EveryFilterHasItsLookup) {
    for (const shadowmap::ShadowSettings& settings : everyChoiceOf("filter"))
        EXPECT_EQ(shadowmap::mapLookup(settings.filter).filter(), settings.filter) << toString(settings.filter);
    EXPECT_TRUE(shadowmap::mapLookup(shadowmap::Filter::Pcf).bilinearCompare());
    EXPECT_FALSE(shadowmap::mapLookup(shadowmap::Filter::Nearest).bilinearCompare());
}

TEST(Techniques, EachLightTypeGetsItsProjection) {
    using Type = engine::Light::Type;
    EXPECT_EQ(shadowmap::projectionFor(Type::Point, 1).kind(), MapKind::Cube);
    EXPECT_EQ(shadowmap::projectionFor(Type::Spot, 1).kind(), MapKind::Map2D);
    EXPECT_EQ(shadowmap::projectionFor(Type::Spot, 3).kind(), MapKind::Map2D);
    EXPECT_EQ(shadowmap::projectionFor(Type::Directional, 1).kind(), MapKind::Map2D);
    EXPECT_EQ(shadowmap::projectionFor(Type::Directional, 2).kind(), MapKind::Cascades);
    // A shadow distance slices the view even for one map (it is where the slice ends).
    EXPECT_EQ(shadowmap::projectionFor(Type::Directional, 1, 20.0).kind(), MapKind::Cascades);
    EXPECT_EQ(shadowmap::projectionFor(Type::Spot, 1, 20.0).kind(), MapKind::Map2D);
    EXPECT_EQ(shadowmap::mapProjection(MapKind::None), nullptr);
    for (const MapKind kind : {MapKind::Map2D, MapKind::Cube, MapKind::Cascades})
        EXPECT_EQ(shadowmap::mapProjection(kind)->kind(), kind);
}

struct CountingAllocator : engine::ResourceAllocator {
    std::uint32_t next = 100;
    int live = 0;
    std::uint32_t acquire(const engine::TextureDesc&) override {
        ++live;
        return next++;
    }
    void release(std::uint32_t, const engine::TextureDesc&) override { --live; }
};

// One light's layers through a depth technique on a graph whose output is the map: what
// runs, in which order, and what each pass drew.
struct LayerRun {
    std::vector<std::string> declared;  // the passes the technique said it added, by name
    std::vector<std::string> executed;  // the graph's execution order
    // In order: "draw PASS" per caster draw, "peel PASS" for one peeling against a first
    // layer, "done" when a layer says it is complete.
    std::vector<std::string> events;
    std::vector<const shadowmap::DepthProgram*> programs;  // per caster draw, the program it drew with
    std::vector<unsigned> inputTextures;                   // per caster draw, the texture its program read
    int transientsLeft = 0;
};

LayerRun run(shadowmap::Variant variant, const std::vector<MapLayer>& layers) {
    LightState light;
    light.name = "lamp";
    light.slot = 2;
    light.settings.variant = variant;
    light.settings.resolution = 64;
    light.frame.kind = layers.size() > 1 ? MapKind::Cube : MapKind::Map2D;
    const DepthTechnique& technique = *shadowmap::depthTechnique(variant);
    LayerRun result;
    engine::RenderGraph graph;
    const engine::TextureDesc desc{64, 64, engine::TextureFormat::Depth24, 1, layers.size() > 1};
    engine::ResourceHandle map = graph.importTexture(light.mapResource(), desc, 7);
    const shadowmap::CasterDraw draw = [&result](engine::PassContext& context, const glm::dmat4&,
                                                 const shadowmap::DepthPassStyle& style) {
        result.events.push_back((style.program != &shadowmap::nearestDepthProgram() ? "peel " : "draw ") + context.passName());
        result.programs.push_back(style.program);
        result.inputTextures.push_back(style.inputTexture);
    };
    std::vector<engine::PassId> added;
    for (const MapLayer& layer : layers)
        technique.addLayerPasses({graph, light, map, layer, shadowmap::DepthPassStyle{}, draw,
                                  [&result] { result.events.push_back("done"); }, added});
    graph.markOutput(map);
    CountingAllocator allocator;
    graph.execute(allocator);
    for (const engine::PassId pass : added) result.declared.push_back(graph.reports().at(pass.index).name);
    result.executed = graph.executionOrder();
    result.transientsLeft = allocator.live;
    return result;
}

const std::vector<MapLayer> kOneMap = {{-1, glm::dmat4(1.0), true, -1, 42}};
// Two cube faces: one with casters, one only cleared.
const std::vector<MapLayer> kTwoFaces = {{0, glm::dmat4(1.0), true, -1, 0}, {1, glm::dmat4(1.0), false, -1, 42}};

TEST(Techniques, StandardAndBackfaceDrawEachLayerInOnePass) {
    for (const auto variant : {shadowmap::Variant::Standard, shadowmap::Variant::Backface}) {
        const LayerRun map = run(variant, kOneMap);
        EXPECT_EQ(map.declared, std::vector<std::string>{"shadow_2_lamp"});
        EXPECT_EQ(map.executed, map.declared);
        EXPECT_EQ(map.events, (std::vector<std::string>{"draw shadow_2_lamp", "done"}));
        const LayerRun faces = run(variant, kTwoFaces);
        EXPECT_EQ(faces.declared, (std::vector<std::string>{"shadow_2_lamp_+x", "shadow_2_lamp_-x"}));
        EXPECT_EQ(faces.executed, faces.declared);
        // -x is only cleared: no draw, and done all the same.
        EXPECT_EQ(faces.events, (std::vector<std::string>{"draw shadow_2_lamp_+x", "done", "done"}));
    }
}

TEST(Techniques, WooDrawsTheFirstLayerThenPeelsItAndOnlyClearsALayerWithoutCasters) {
    const LayerRun faces = run(shadowmap::Variant::Woo, kTwoFaces);
    const std::vector<std::string> passes = {"shadow_2_lamp_+x_first_layer", "shadow_2_lamp_+x", "shadow_2_lamp_-x"};
    EXPECT_EQ(faces.declared, passes);
    EXPECT_EQ(faces.executed, passes);
    // The layer is done after its peel, not after its first layer.
    EXPECT_EQ(faces.events, (std::vector<std::string>{"draw shadow_2_lamp_+x_first_layer", "peel shadow_2_lamp_+x",
                                                      "done", "done"}));
    EXPECT_EQ(faces.transientsLeft, 0);  // the first layer went back to the allocator
    // The peel reads the first layer (the allocator's first texture) and closes with the far
    // plane as a full-screen layer; the first layer is drawn as by standard.
    ASSERT_EQ(faces.programs.size(), 2u);
    EXPECT_EQ(faces.programs[0], &shadowmap::nearestDepthProgram());
    EXPECT_EQ(faces.inputTextures[0], 0u);
    EXPECT_TRUE(faces.programs[1]->drawsFullScreenLayer);
    EXPECT_EQ(faces.inputTextures[1], 100u);
}

// The plugin compiles depthPrograms() before the first frame: a program a pass draws with
// that is missing there would compile on a light's first use, mid-frame.
TEST(Techniques, EveryProgramAPassDrawsWithIsAmongTheProgramsCompiledBeforeTheFirstFrame) {
    const std::vector<const shadowmap::DepthProgram*> compiled = shadowmap::depthPrograms();
    for (const shadowmap::ShadowSettings& settings : everyChoiceOf("variant")) {
        if (!shadowmap::usesDepthMap(settings.variant)) continue;
        const std::vector<const shadowmap::DepthProgram*> declared =
            shadowmap::depthTechnique(settings.variant)->programs();
        for (const auto& layers : {kOneMap, kTwoFaces})
            for (const shadowmap::DepthProgram* program : run(settings.variant, layers).programs) {
                EXPECT_NE(std::find(declared.begin(), declared.end(), program), declared.end())
                    << toString(settings.variant) << " draws with " << program->name << " without declaring it";
                EXPECT_NE(std::find(compiled.begin(), compiled.end(), program), compiled.end()) << program->name;
            }
    }
    // Each once: the standard program is every technique's.
    for (const shadowmap::DepthProgram* program : compiled)
        EXPECT_EQ(std::count(compiled.begin(), compiled.end(), program), 1) << program->name;
}

// Backface draws the casters that are not closed meshes two-sided; which ones it found is
// its own report (LightShadowFrame::openCasters, printed as --stats open_casters), named
// by node and with one warning per light however many.
TEST(Techniques, BackfaceFindsTheOpenCastersAndNamesThemInOneWarning) {
    engine::Scene scene;
    const std::vector<std::string> names = {"closed box", "sheet", "", "receiver only", "cloth", "flag", "leaf"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        engine::Node node;
        node.name = names[i];
        scene.nodes.push_back(node);
        engine::MeshInstance instance;
        instance.node = static_cast<int>(i);
        instance.mesh = static_cast<int>(i);
        instance.castShadows = names[i] != "receiver only";
        scene.meshInstances.push_back(instance);
    }
    const std::vector<bool> closedMeshes = {true, false, false, false, false, false, false};
    LightState light;
    shadowmap::DepthPassStyle style;
    shadowmap::depthTechnique(shadowmap::Variant::Backface)->adjustStyle(light, {scene, closedMeshes}, style);
    EXPECT_TRUE(style.backFacesOnly);
    EXPECT_EQ(style.closedMeshes, &closedMeshes);
    // A node without a name by its index; a caster that casts no shadow is not one.
    EXPECT_EQ(light.frame.openCasters, (std::vector<std::string>{"sheet", "node 2", "cloth", "flag", "leaf"}));
    ASSERT_EQ(light.frame.warnings.size(), 1u);
    EXPECT_NE(light.frame.warnings[0].find("5 caster(s) not closed"), std::string::npos) << light.frame.warnings[0];
    EXPECT_EQ(light.frame.warnings[0].find("flag"), std::string::npos) << "names only the first three";

    LightState allClosed;
    const std::vector<bool> everyMeshClosed(names.size(), true);
    shadowmap::depthTechnique(shadowmap::Variant::Backface)->adjustStyle(allClosed, {scene, everyMeshClosed}, style);
    EXPECT_TRUE(allClosed.frame.openCasters.empty());
    EXPECT_TRUE(allClosed.frame.warnings.empty());
}

} // namespace
