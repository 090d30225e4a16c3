// Stenciled shadow volumes (variant volume) against visibility computed analytically: boxes
// over a floor slab lit by each light type, a grazing light, the camera inside a volume, an
// open double-sided sheet and two intersecting boxes. Volumes are exact at pixel centres, so
// pixels at the shadow's edges are evaluated too (edgeRadius 0), unlike the map tests.
//
// Tolerance: the bound, 0.02% of the evaluated floor pixels (2 of the ~10,000 here),
// edges included. Measured on llvmpipe: see each test's comment.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include <string>

namespace {

using engine::Light;
using engine::test::SceneBuilder;

constexpr int kWidth = 160, kHeight = 120;
// A pixel centre on an analytic edge is decided by rounding on both sides (the truth's
// segment test in double, the rasterizer's fixed-point coverage): 0.02% of the evaluated
// pixels (2 here) is the bound volumes are held to.
constexpr double kMaxWrongFraction = 0.0002;
const engine::Aabb kFloor{{-10, -0.2, -10}, {10, 0, 10}};
const engine::Aabb kBox{{-1, 1, -1}, {1, 3, 1}};
const nlohmann::json kVolume = {{"variant", "volume"}};

engine::FrameCamera overview() { return engine::test::cameraLooking({0, 16, 7}, {0, 0, 0.5}, kWidth, kHeight); }

const auto kEverywhere = [](const glm::dvec3&) { return true; };

// A square sheet of two triangles at height y, one-sided geometry with a double-sided
// material: it shadows whichever side faces the light.
int addSheet(SceneBuilder& builder, double y, double half) {
    engine::Material twoSided = builder.scene.materials.front();
    twoSided.doubleSided = true;
    builder.scene.materials.push_back(twoSided);
    engine::Primitive primitive;
    const float h = static_cast<float>(half);
    primitive.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    primitive.normals.assign(4, {0, 1, 0});
    primitive.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
    primitive.material = static_cast<int>(builder.scene.materials.size()) - 1;
    engine::Mesh mesh;
    mesh.name = "sheet";
    mesh.primitives.push_back(primitive);
    builder.scene.meshes.push_back(mesh);
    engine::Node node;
    node.name = "sheet";
    node.mesh = static_cast<int>(builder.scene.meshes.size()) - 1;
    node.local = glm::translate(glm::dmat4(1.0), glm::dvec3(0, y, 0));
    return builder.addNode(node);
}

// A builder holding a volume-shadowed light and the floor slab; with `box`, the box over it.
SceneBuilder litFloor(const char* name, Light::Type type, const glm::dvec3& position, const glm::dvec3& target,
                      bool box = true) {
    SceneBuilder builder;
    builder.addLight(name, type, position, target, kVolume);
    builder.addBox("floor", kFloor.min, kFloor.max);
    if (box) builder.addBox("box", kBox.min, kBox.max);
    return builder;
}

// The sun the directional scenes share: above and behind the box, toward the camera's left.
const glm::dvec3 kSunPosition{-5, 6, -5};

// Every test runs with the volumes made on the CPU (closed casters' counted with z-pass where
// they cannot hold the camera), on the CPU all counted with z-fail (volume_counting), and with
// those of closed casters made in a geometry shader (volume_extrusion): all must be exact.
class ShadowVolume : public engine::test::ShadowPluginTest, public ::testing::WithParamInterface<const char*> {
protected:
    void SetUp() override {
        if (loaded_ == GetParam()) return;
        const std::string mode = GetParam();
        loadPlugin({{"volume_extrusion", mode == "gpu" ? "gpu" : "cpu"},
                    {"volume_counting", mode == "cpu_z_fail" ? "z-fail" : "auto"}});
        loaded_ = GetParam();
    }
    static void TearDownTestSuite() {
        ShadowPluginTest::TearDownTestSuite();
        loaded_.clear();
    }
    static inline std::string loaded_;

    engine::test::MaskStats compare(const engine::Scene& scene, const engine::FrameCamera& camera,
                                    const std::vector<engine::Aabb>& occluders,
                                    const std::function<bool(const glm::dvec3&)>& inside = kEverywhere) {
        const auto mask = engine::test::renderShadowMask(plugins(), scene, camera, 0);
        return engine::test::compareFloorMask(mask, scene, 0, camera, occluders, 0.0, 9.9, inside, 0);
    }
};

} // namespace

TEST_P(ShadowVolume, SpotLightIsExactEdgesIncluded) {
    SceneBuilder builder = litFloor("spot", Light::Type::Spot, {-4, 8, -4}, {1.5, 0, 1.5});
    const engine::Scene scene = builder.build();
    const glm::dvec3 apex(-4, 8, -4);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.5, 0, 1.5) - apex);
    // Inside the cone (outside it the light reaches nothing, whatever the visibility says).
    const auto inCone = [&](const glm::dvec3& p) { return std::acos(glm::dot(glm::normalize(p - apex), axis)) < 0.7; };
    const auto result = compare(scene, overview(), {kFloor, kBox}, inCone);
    EXPECT_GT(result.truthShadowed, 200);
    EXPECT_GT(result.truthLit, 1000);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

TEST_P(ShadowVolume, DirectionalLightIsExactEdgesIncluded) {
    SceneBuilder builder = litFloor("sun", Light::Type::Directional, kSunPosition, {0, 0, 0});
    const auto result = compare(builder.build(), overview(), {kFloor, kBox});
    EXPECT_GT(result.truthShadowed, 200);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

TEST_P(ShadowVolume, PointLightIsExactEdgesIncluded) {
    SceneBuilder builder = litFloor("bulb", Light::Type::Point, {0.3, 5, 0.2}, {0.3, 0, 0.2});
    const auto result = compare(builder.build(), overview(), {kFloor, kBox});
    EXPECT_GT(result.truthShadowed, 200);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

// The sun 10 degrees above the horizon: a shadow five times longer than the box is tall,
// whose sides meet the floor at a grazing angle.
TEST_P(ShadowVolume, GrazingLightIsExactEdgesIncluded) {
    const double elevation = glm::radians(10.0);
    SceneBuilder builder =
        litFloor("low sun", Light::Type::Directional, {-std::cos(elevation), std::sin(elevation), -0.3}, {0, 0, 0});
    const auto result = compare(builder.build(), overview(), {kFloor, kBox});
    EXPECT_GT(result.truthShadowed, 500);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

// The camera under the box, inside its volume, looking out across the floor: z-fail counts
// only what lies behind the nearest surface, so the volume faces in front of the camera (or
// clipped by its near plane) change nothing.
TEST_P(ShadowVolume, CameraInsideAVolumeIsExact) {
    SceneBuilder builder = litFloor("bulb", Light::Type::Point, {0.3, 6, 0.2}, {0.3, 0, 0.2});
    const engine::FrameCamera camera = engine::test::cameraLooking({0.2, 0.6, 0.1}, {4, 0, 3}, kWidth, kHeight);
    const engine::Scene scene = builder.build();
    {
        // The box's volume holds the camera: it must be counted with z-fail (the floor's may
        // take z-pass on the CPU).
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = camera;
        const nlohmann::json stats =
            renderer.renderFrame(request).pluginStats.at("shadowmap_plugin").at("lights").at(0);
        EXPECT_LE(stats.at("casters_z_pass").get<int>(), 1) << stats;
    }
    const auto result = compare(scene, camera, {kFloor, kBox});
    EXPECT_GT(result.truthShadowed, 200);
    EXPECT_GT(result.truthLit, 200);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

// An open mesh: a double-sided sheet shadows the floor whether its triangles face the light
// or face away from it (turned over by a half turn about x).
TEST_P(ShadowVolume, OpenSheetShadowsWhicheverSideFacesTheLight) {
    for (const bool turnedOver : {false, true}) {
        SCOPED_TRACE(turnedOver ? "triangles facing away from the light" : "triangles facing the light");
        SceneBuilder builder = litFloor("bulb", Light::Type::Point, {0.4, 6, 0.3}, {0.4, 0, 0.3}, false);
        const int sheet = addSheet(builder, 2.0, 1.0);
        if (turnedOver)
            builder.scene.nodes[sheet].local = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 2, 0)) *
                                               glm::rotate(glm::dmat4(1.0), glm::pi<double>(), glm::dvec3(1, 0, 0));
        const engine::Aabb sheetBox{{-1, 2, -1}, {1, 2, 1}};
        const auto result = compare(builder.build(), overview(), {kFloor, sheetBox});
        EXPECT_GT(result.truthShadowed, 200);
        EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
    }
}

// Two boxes that overlap: a floor point behind both is inside two volumes (count 2), one
// behind either inside one; every such point is shadowed.
TEST_P(ShadowVolume, IntersectingCastersAreExact) {
    SceneBuilder builder = litFloor("sun", Light::Type::Directional, kSunPosition, {0, 0, 0});
    const engine::Aabb second{{0, 1.5, -0.5}, {2.5, 2.5, 0.5}};
    builder.addBox("crossing box", second.min, second.max);
    const auto result = compare(builder.build(), overview(), {kFloor, kBox, second});
    EXPECT_GT(result.truthShadowed, 300);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

// The same scene 10^7 units up, where float spacing is 1.0: the volumes are composed in
// double and rounded to float relative to the camera, so the shadow is as exact as at 0.
TEST_P(ShadowVolume, CastersFarFromTheOriginAreExact) {
    const glm::dvec3 far(0, 1e7, 0);
    SceneBuilder builder;
    builder.addLight("bulb", Light::Type::Point, glm::dvec3(0.3, 5, 0.2) + far, glm::dvec3(0.3, 0, 0.2) + far, kVolume);
    const engine::Aabb floor{kFloor.min + far, kFloor.max + far}, box{kBox.min + far, kBox.max + far};
    builder.addBox("floor", floor.min, floor.max);
    builder.addBox("box", box.min, box.max);
    const engine::Scene scene = builder.build();
    const engine::FrameCamera camera =
        engine::test::cameraLooking(glm::dvec3(0, 16, 7) + far, glm::dvec3(0, 0, 0.5) + far, kWidth, kHeight);
    const auto mask = engine::test::renderShadowMask(plugins(), scene, camera, 0);
    const auto result = engine::test::compareFloorMask(mask, scene, 0, camera, {floor, box}, far.y, 9.9, kEverywhere, 0);
    EXPECT_GT(result.truthShadowed, 200);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

// A still camera, light and scene keep the visibility of the frame before: no volume pass.
// Moving the light makes it again, and the mask follows. The pass's fill (stencil_fragments)
// is 0 when it does not run, and when it runs at least one counting sample lies behind each
// shadowed pixel (a count of 0 there would light it).
TEST_P(ShadowVolume, AStillFrameReusesTheVisibilityAndAMovedLightRemakesIt) {
    SceneBuilder builder = litFloor("sun", Light::Type::Directional, kSunPosition, {0, 0, 0});
    engine::Scene scene = builder.build();
    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = overview();
    request.shadowMaskSlots = {0};
    request.timing = true;  // waits for the frame, so the fill's count is there to read
    nlohmann::json stats;
    const auto rendered = [&] {
        const engine::FrameResult result = renderer.renderFrame(request);
        EXPECT_EQ(result.shadowViews.size(), 1u);
        // Floor and box are closed: with volume_extrusion "gpu" the geometry shader makes both
        // volumes (when the frame makes them at all).
        stats = result.pluginStats.at("shadowmap_plugin").at("lights").at(0);
        if (result.shadowViews.at(0).renderedThisFrame) {
            EXPECT_EQ(stats.at("casters_extruded_on_gpu"), std::string(GetParam()) == "gpu" ? 2 : 0) << stats;
            // Seen from above, neither volume can hold the camera: the CPU counts both with
            // z-pass, without caps, unless asked for z-fail (the geometry shader's are z-fail).
            EXPECT_EQ(stats.at("casters_z_pass"), std::string(GetParam()) == "cpu" ? 2 : 0) << stats;
        } else {
            EXPECT_EQ(stats.at("stencil_fragments"), 0) << stats;
        }
        EXPECT_TRUE(result.shadowViews.at(0).hasScreenVisibility);
        return result.shadowViews.at(0).renderedThisFrame;
    };
    EXPECT_TRUE(rendered());
    const std::vector<std::uint8_t> first = renderer.readShadowMask(0);
    const auto firstMask = engine::test::compareFloorMask(first, scene, 0, overview(), {kFloor, kBox}, 0.0, 9.9,
                                                          kEverywhere, 0);
    ASSERT_TRUE(stats.at("stencil_fragments").is_number()) << stats;
    EXPECT_GE(stats.at("stencil_fragments").get<std::int64_t>(), firstMask.truthShadowed) << stats;
    EXPECT_FALSE(rendered());
    EXPECT_EQ(renderer.readShadowMask(0), first);

    scene.nodes[0].local = engine::test::placeLooking({5, 6, -5}, {0, 0, 0});
    scene.updateWorldTransforms();
    EXPECT_TRUE(rendered());
    const auto moved = engine::test::compareFloorMask(renderer.readShadowMask(0), scene, 0, overview(),
                                                      {kFloor, kBox}, 0.0, 9.9, kEverywhere, 0);
    EXPECT_GT(moved.truthShadowed, 200);
    EXPECT_LE(moved.wrongFraction(), kMaxWrongFraction);
    ASSERT_TRUE(stats.at("stencil_fragments").is_number()) << stats;
    EXPECT_GE(stats.at("stencil_fragments").get<std::int64_t>(), moved.truthShadowed) << stats;
}

// A frame that reads the light's map back (a viewer's map view) gets the count of volumes at
// each pixel instead: on the floor under the sun, 0 where truth is lit and 1 where the box
// shadows it (the floor's own volume counts 0 on its lit top), so "count 0" is held to the
// same bound against truth as the visibility. A frame that stops asking keeps its cache.
TEST_P(ShadowVolume, AMapReadbackGetsTheStencilCountsAgreeingWithTruth) {
    SceneBuilder builder = litFloor("sun", Light::Type::Directional, kSunPosition, {0, 0, 0});
    const engine::Scene scene = builder.build();
    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = overview();
    request.shadowMapSlots = {0};
    const engine::FrameResult result = renderer.renderFrame(request);
    ASSERT_EQ(result.stencilCounts.count(0), 1u);
    EXPECT_EQ(result.shadowMaps.count(0), 0u);  // no map: the counts are in its place
    const engine::StencilCountReadback& counts = result.stencilCounts.at(0);
    ASSERT_EQ(counts.width, kWidth);
    ASSERT_EQ(counts.height, kHeight);
    ASSERT_EQ(counts.counts.size(), std::size_t(kWidth) * kHeight);
    std::vector<std::uint8_t> litWhereZero(counts.counts.size());
    for (std::size_t i = 0; i < counts.counts.size(); ++i) litWhereZero[i] = counts.counts[i] == 0 ? 255 : 0;
    const auto stats = engine::test::compareFloorMask(litWhereZero, scene, 0, overview(), {kFloor, kBox}, 0.0, 9.9,
                                                      kEverywhere, 0);
    EXPECT_GT(stats.truthShadowed, 200);
    EXPECT_LE(stats.wrongFraction(), kMaxWrongFraction);
    int ones = 0, more = 0;
    engine::test::forEachFloorPixel(overview(), 0.0, 9.9, [&](int x, int y, const glm::dvec3&) {
        const std::uint8_t count = counts.counts[std::size_t(y) * kWidth + x];
        ones += count == 1;
        more += count > 1;
    });
    EXPECT_GE(ones, stats.truthShadowed - 2);  // the bound's 2 pixels
    EXPECT_EQ(more, 0);

    request.shadowMapSlots.clear();
    const engine::FrameResult still = renderer.renderFrame(request);
    EXPECT_FALSE(still.shadowViews.at(0).renderedThisFrame);
    EXPECT_TRUE(still.stencilCounts.empty());
}

// A mirroring node (scale -1) turns its caster's triangles clockwise, so its volume would count
// -1 inside where an overlapping unmirrored caster's counts +1: together, light. Rewound, both
// shadow.
TEST_P(ShadowVolume, AMirroredCasterOverlappingAnotherShadowsAsBoth) {
    SceneBuilder builder = litFloor("sun", Light::Type::Directional, kSunPosition, {0, 0, 0});
    const engine::Aabb second{{0, 1.5, -0.5}, {2.5, 2.5, 0.5}};
    const int mirrored = builder.addBox("mirrored box", second.min, second.max);
    builder.scene.nodes[mirrored].local = builder.scene.nodes[mirrored].local * glm::scale(glm::dmat4(1.0), {-1, 1, 1});
    const auto result = compare(builder.build(), overview(), {kFloor, kBox, second});
    EXPECT_GT(result.truthShadowed, 300);
    EXPECT_LE(result.wrongFraction(), kMaxWrongFraction);
}

INSTANTIATE_TEST_SUITE_P(Extrusion, ShadowVolume, ::testing::Values("cpu", "cpu_z_fail", "gpu"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });
