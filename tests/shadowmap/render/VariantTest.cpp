// The woo (midpoint) and backface variants against the standard one, on analytic scenes.
// Acne = truth-lit floor pixels the mask calls shadowed, over truth-lit pixels; leak =
// truth-shadowed pixels it calls lit, over truth-shadowed ones; 2 px around analytic edges
// are left out (see ShadowMaskTest.cpp for why).
//
// Measured on llvmpipe (Mesa 22.3), 1024 maps, 240x180: woo and backface have 0 acne and
// 0 leak pixels in every scene here (of 23000-24000 truth-lit and 355-1578 truth-shadowed
// pixels); standard without polygon offset 49.7 % acne. Bounds: kStrayPixels wrong pixels of
// each kind, for a rasterizer that rounds an edge texel differently; a real fault (an acne
// band, light under a contact) is hundreds of pixels.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

namespace {

using engine::Light;
using engine::test::SceneBuilder;

constexpr int kWidth = 240, kHeight = 180;
const engine::Aabb kFloor{{-10, -0.2, -10}, {10, 0, 10}};

engine::FrameCamera camera() {
    return engine::test::cameraLooking({0, 14, 8}, {0, 0, 0.5}, kWidth, kHeight);
}

constexpr int kStrayPixels = 3;

const auto kEverywhere = [](const glm::dvec3&) { return true; };

class ShadowVariants : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 1024}}); }

    // A spot light at a moderate angle over the floor and the given boxes, with `shadow`
    // settings on the light; returns the mask's agreement with the analytic truth.
    engine::test::MaskStats measure(const std::vector<engine::Aabb>& boxes, const nlohmann::json& shadow,
                                    engine::FrameResult* frame = nullptr) {
        SceneBuilder builder;
        builder.addBox("floor", kFloor.min, kFloor.max);
        for (std::size_t i = 0; i < boxes.size(); ++i)
            builder.addBox("box" + std::to_string(i), boxes[i].min, boxes[i].max);
        const glm::dvec3 apex(-5, 7, -3), target(1, 0, 1);
        builder.addLight("spot", Light::Type::Spot, apex, target, shadow, 0.75);
        const engine::Scene scene = builder.build();
        std::vector<engine::Aabb> occluders = boxes;
        occluders.push_back(kFloor);
        const auto mask = engine::test::renderShadowMask(plugins(), scene, camera(), 0, frame);
        const glm::dvec3 axis = glm::normalize(target - apex);
        const auto inCone = [&](const glm::dvec3& p) {
            return std::acos(glm::dot(glm::normalize(p - apex), axis)) < 0.75 - 0.03;
        };
        return engine::test::compareFloorMask(mask, scene, 0, camera(), occluders, 0.0, 9.9, inCone);
    }
};

const std::vector<engine::Aabb> kFloatingBox{{{-1, 1, -1}, {1, 2.5, 1}}};

} // namespace

TEST_F(ShadowVariants, WithoutPolygonOffsetOnlyStandardShowsAcne) {
    // No bias at all: the normal offset (NormalOffsetTest) would hide the acne this shows.
    const nlohmann::json noOffset{{"polygon_offset", {0.0, 0.0}}, {"normal_offset", 0.0}, {"filter", "nearest"}};
    nlohmann::json standard = noOffset, woo = noOffset, backface = noOffset;
    standard["variant"] = "standard";
    woo["variant"] = "woo";
    backface["variant"] = "backface";
    const auto standardResult = measure(kFloatingBox, standard);
    const auto wooResult = measure(kFloatingBox, woo);
    const auto backfaceResult = measure(kFloatingBox, backface);
    std::printf("acne without offset: standard %.2f%%, woo %.3f%%, backface %.3f%%\n",
                100 * standardResult.acneFraction(), 100 * wooResult.acneFraction(),
                100 * backfaceResult.acneFraction());
    EXPECT_GT(standardResult.truthLit, 2000);
    // Self-shadowing on the lit floor: measured 49.7 %; bound 40 %, the acne must be the
    // band over the lit floor, not a few stray texels.
    EXPECT_GT(standardResult.acneFraction(), 0.40);
    EXPECT_LE(wooResult.acne, kStrayPixels);
    EXPECT_LE(backfaceResult.acne, kStrayPixels);
}

TEST_F(ShadowVariants, ThinPlankCastsWithoutLeakOrAcne) {
    // A plank 4 cm thick, 1 m above the floor: its shadow must not leak light, and its
    // midpoint (woo) sits only 2 cm under its top.
    const std::vector<engine::Aabb> plank{{{-1.5, 1.0, -0.5}, {1.5, 1.04, 0.5}}};
    for (const char* variant : {"woo", "backface"}) {
        const auto result = measure(plank, {{"variant", variant}});
        std::printf("%s thin plank: leak %.3f%%, acne %.3f%%\n", variant,
                    100 * result.leakFraction(), 100 * result.acneFraction());
        EXPECT_GT(result.truthShadowed, 200) << variant;
        EXPECT_LE(result.leak, kStrayPixels) << variant;
        EXPECT_LE(result.acne, kStrayPixels) << variant;
    }
}

TEST_F(ShadowVariants, BoxRestingOnTheFloorKeepsItsContactShadow) {
    // Contact: the box's shadow starts right at its base; no light may leak under it.
    const std::vector<engine::Aabb> resting{{{-1, 0, -1}, {1, 1.5, 1}}};
    for (const char* variant : {"woo", "backface"}) {
        const auto result = measure(resting, {{"variant", variant}});
        std::printf("%s contact: leak %.3f%%, acne %.3f%%\n", variant, 100 * result.leakFraction(),
                    100 * result.acneFraction());
        EXPECT_GT(result.truthShadowed, 200) << variant;
        EXPECT_LE(result.leak, kStrayPixels) << variant;
        EXPECT_LE(result.acne, kStrayPixels) << variant;
    }
}

TEST_F(ShadowVariants, OpenCasterUnderBackfaceIsReportedAndStillCasts) {
    // A single quad (open: its edges have one triangle each) floating over the floor.
    SceneBuilder builder;
    builder.addBox("floor", kFloor.min, kFloor.max);
    engine::Primitive quad;
    quad.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
    quad.normals.assign(4, glm::vec3(0, 1, 0));
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    for (const auto& p : quad.positions) quad.bounds.extend(glm::dvec3(p));
    engine::Mesh mesh;
    mesh.name = "sheet";
    mesh.primitives = {quad};
    mesh.bounds = quad.bounds;
    mesh.closed = false;
    builder.scene.meshes.push_back(mesh);
    engine::Node node;
    node.name = "sheet";
    node.mesh = static_cast<int>(builder.scene.meshes.size()) - 1;
    node.local = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 2, 0));
    builder.addNode(node);
    const glm::dvec3 apex(-5, 7, -3), target(1, 0, 1);
    builder.addLight("spot", Light::Type::Spot, apex, target, {{"variant", "backface"}}, 0.75);
    const engine::Scene scene = builder.build();

    const auto mask = engine::test::renderShadowMask(plugins(), scene, camera(), 0);
    // Drawn as a closed mesh (front faces culled) the sheet, facing the light, would cast
    // nothing: its shadow below says backface found it open (TechniquesTest checks the finding).
    const engine::Aabb sheet{{-1, 2, -1}, {1, 2, 1}};
    const glm::dvec3 axis = glm::normalize(target - apex);
    const auto result = engine::test::compareFloorMask(
        mask, scene, 0, camera(), {kFloor, sheet}, 0.0, 9.9, [&](const glm::dvec3& p) {
            return std::acos(glm::dot(glm::normalize(p - apex), axis)) < 0.72;
        });
    EXPECT_GT(result.truthShadowed, 200);  // the sheet's shadow is on the floor ...
    EXPECT_LE(result.leak, kStrayPixels);  // ... and the mask has it
    EXPECT_LE(result.acne, kStrayPixels);
}

TEST_F(ShadowVariants, WooMapHoldsTheMidpointOfTheFirstTwoLayers) {
    // Known layers under a sun straight overhead (orthographic: depth is linear in height):
    // a plate from y = 2.0 to 2.5 over a floor slab from y = -0.2 to 0. Every texel must
    // hold the midpoint of the two layers it sees (plate: y = 2.25; floor: y = -0.1), or
    // far (1.0) where nothing was drawn twice.
    SceneBuilder builder;
    builder.addBox("floor", kFloor.min, kFloor.max);
    builder.addBox("plate", {-1, 2.0, -1}, {1, 2.5, 1});
    builder.addLight("sun", Light::Type::Directional, {0, 10, 0}, {0, 0, 0},
                     {{"variant", "woo"}, {"resolution", 256}, {"depth_format", "d24"}});
    const engine::Scene scene = builder.build();

    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = camera();
    request.shadowMapSlots = {0};
    const engine::FrameResult frame = renderer.renderFrame(request);
    ASSERT_EQ(frame.shadowMaps.count(0), 1u);
    const engine::DepthReadback& map = frame.shadowMaps.at(0);

    const engine::ShadowView* view = frame.shadowView(0);
    ASSERT_TRUE(view && view->hasMap && view->layers.size() == 1u);
    const double nearPlane = view->nearPlane, farPlane = view->farPlane;
    const glm::dmat4 lightToWorld = view->layers[0].lightToWorld;
    const glm::dvec3 origin(lightToWorld[3]), forward = -glm::dvec3(lightToWorld[2]);
    const auto windowDepth = [&](double y) {  // orthographic: linear in distance
        return (glm::dot(glm::dvec3(0, y, 0) - origin, forward) - nearPlane) / (farPlane - nearPlane);
    };
    const double plateMid = windowDepth(2.25), floorMid = windowDepth(-0.1);
    const double tolerance = 2.0 / 16777215.0;  // two d24 steps (measured: 0.6)
    int plate = 0, floor = 0, far = 0, other = 0;
    double worst = 0.0;
    for (float depth : map.depth) {
        const double toPlate = std::abs(depth - plateMid), toFloor = std::abs(depth - floorMid);
        if (toPlate <= tolerance) ++plate;
        else if (toFloor <= tolerance) ++floor;
        else if (depth == 1.0f) ++far;
        else ++other;
        if (depth < 1.0f) worst = std::max(worst, std::min(toPlate, toFloor));
    }
    std::printf("texels: plate midpoint %d, floor midpoint %d, far %d, other %d; "
                "worst deviation %.3g (%.2f d24 steps)\n",
                plate, floor, far, other, worst, worst * 16777215.0);
    EXPECT_GT(plate, 100);
    EXPECT_GT(floor, 1000);
    EXPECT_EQ(other, 0);
}

// A read-back map says whether its layers are a cube's faces (the tools label them by it),
// rather than leaving the tools to guess from the layer count.
TEST_F(ShadowVariants, AReadBackMapSaysWhetherItIsACube) {
    SceneBuilder builder;
    builder.addBox("floor", kFloor.min, kFloor.max);
    builder.addBox("plate", {-1, 2.0, -1}, {1, 2.5, 1});
    builder.addLight("sun", Light::Type::Directional, {0, 10, 0}, {0, 0, 0}, {{"resolution", 64}});
    builder.addLight("bulb", Light::Type::Point, {0, 4, 0}, {0, 0, 0}, {{"resolution", 64}});
    const engine::Scene scene = builder.build();

    engine::Renderer renderer({}, plugins());
    renderer.setScene(scene);
    engine::FrameRequest request;
    request.camera = camera();
    request.shadowMapSlots = {0, 1};
    const engine::FrameResult frame = renderer.renderFrame(request);
    ASSERT_EQ(frame.shadowMaps.count(0), 1u);
    ASSERT_EQ(frame.shadowMaps.count(1), 1u);
    EXPECT_FALSE(frame.shadowMaps.at(0).cube);
    EXPECT_TRUE(frame.shadowMaps.at(1).cube);
    EXPECT_EQ(frame.shadowMaps.at(1).layers, 6);
    EXPECT_EQ(frame.shadowMaps.at(1).depth.size(), 6u * 64u * 64u);
}
