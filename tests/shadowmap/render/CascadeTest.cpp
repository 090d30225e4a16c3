// Cascaded shadow maps for a directional light on a large outdoor scene
// (tests/support/OutdoorScene.h), against analytic truth: near the camera, cascades must cut
// the error of one map of the same resolution at least five-fold; on a slow walk stable far
// cascades are kept from the cache; and stable cascades shimmer less than fitted ones.
#include "../../gl/GlTestContext.h"
#include "OutdoorGroundErrors.h"

namespace {

using engine::test::OutdoorScene;

constexpr int kWidth = 480, kHeight = 270;
constexpr double kNearCamera = 25.0;  // metres: "near the camera"

class Cascades : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 1024}}); }

    // The sun's shadow mask with `shadow` settings, against the analytic truth on ground
    // pixels within kNearCamera of the camera.
    // `sun`, when given, receives the sun's shadow view.
    engine::test::MaskStats nearCameraErrors(const nlohmann::json& shadow, engine::ShadowView* sun = nullptr) {
        return engine::test::outdoorGroundErrors(plugins(), shadow, kWidth, kHeight,
                                                 engine::test::withinOfOutdoorCamera(kNearCamera), 2, sun);
    }
};

TEST_F(Cascades, CutTheErrorNearTheCameraFiveFold) {
    engine::ShadowView sun;
    const auto single = nearCameraErrors({{"cascades", 1}});
    const auto cascaded = nearCameraErrors({{"cascades", 4}}, &sun);
    std::printf("near the camera: one map %.3f%%, 4 cascades %.3f%%\n", 100 * single.wrongFraction(),
                100 * cascaded.wrongFraction());
    ASSERT_GT(single.evaluated, 5000);
    ASSERT_GT(single.truthShadowed, 300);  // the posts' shadows are in view
    EXPECT_STREQ(engine::mapKindName(sun), "cascades");
    EXPECT_EQ(sun.layers.size(), 4u);
    // Measured on llvmpipe (1024 maps, 480x270, 50231 pixels evaluated): one map 3.761 %
    // wrong (1634 acne, 255 leak: a texel spans about a metre there), 4 cascades 0.002 %
    // (1 pixel). The issue asks for five-fold; the margin to the measured ~1900-fold is
    // wide because one cascade's worth of acne (hundreds of pixels) must fail it.
    EXPECT_LE(cascaded.wrongFraction(), single.wrongFraction() / 5.0);
}

// cascades: auto (the default) on the street chooses cascades itself, and they hold the
// near-camera accuracy the explicit count gives.
TEST_F(Cascades, TheDefaultChoosesCascadesOnTheStreet) {
    engine::ShadowView sun;
    const auto single = nearCameraErrors({{"cascades", 1}});
    const auto automatic = nearCameraErrors(nlohmann::json::object(), &sun);
    std::printf("near the camera: one map %.3f%%, auto (%zu cascades) %.3f%%\n", 100 * single.wrongFraction(),
                sun.layers.size(), 100 * automatic.wrongFraction());
    EXPECT_STREQ(engine::mapKindName(sun), "cascades");
    // Measured: 3 (gains 1 -> 2 -> 3 -> 4 of the nearest texel about 12, 1.7, 1.3; CascadeFit.h).
    EXPECT_EQ(sun.layers.size(), 3u);
    EXPECT_LE(automatic.wrongFraction(), single.wrongFraction() / 5.0);
}

// shadow_distance on one map: the map covers the view to that depth only, so the shadows
// near the camera sharpen (street, 30 m); past it (a road of blocks, 150 m with shadow_fade
// 0.5) every ground pixel is lit, and over the fade band (75 .. 150 m) a pixel the truth
// shadows, away from shadow edges, reads the fade's share of lit.
TEST_F(Cascades, AShadowDistanceEndsShadowsWithAFadeAndSharpensTheNearOnes) {
    const auto single = nearCameraErrors({{"cascades", 1}});
    const auto sliced = nearCameraErrors({{"cascades", 1}, {"shadow_distance", 30.0}});
    std::printf("near the camera: one map %.3f%%, one map to 30 m %.3f%%\n", 100 * single.wrongFraction(),
                100 * sliced.wrongFraction());
    // Measured (1024 maps, 480x270): 2.656 % against 0.004 %: a texel of a map over the whole
    // street is about a metre, of one to 30 m a few centimetres. Five-fold, as cascades must.
    EXPECT_LE(sliced.wrongFraction(), single.wrongFraction() / 5.0);

    // Blocks 10 m tall every 20 m down a road, seen from 30 m up, lit from the side: wide
    // shadows on the road at every depth. shadow_distance 150 m, fade over its second half.
    constexpr double kDistance = 150.0, kFade = 0.5, kCameraFar = 400.0;
    engine::test::SceneBuilder builder;
    builder.addBox("ground", {-400.0, -0.5, -400.0}, {400.0, 0.0, 400.0});
    std::vector<engine::Aabb> blocks;
    for (int i = 0; i < 16; ++i) {
        const double z = -20.0 * i;
        blocks.push_back({{-20.0, 0.0, z - 12.0}, {-10.0, 10.0, z}});
        builder.addBox("block" + std::to_string(i), blocks.back().min, blocks.back().max);
    }
    const auto sunShadow = [&](const nlohmann::json& shadow) {
        engine::test::SceneBuilder lit = builder;
        lit.addLight("sun", engine::Light::Type::Directional, glm::dvec3(-1.0, 1.0, 0.2) * 100.0, glm::dvec3(0.0), shadow);
        return lit.build();
    };
    const engine::Scene scene = sunShadow({{"cascades", 1}, {"shadow_distance", kDistance}, {"shadow_fade", kFade}});
    const engine::Scene unlimitedScene = sunShadow({{"cascades", 1}});
    engine::FrameCamera camera = engine::test::cameraLooking({0.0, 30.0, 10.0}, {0.0, 0.0, -120.0}, kWidth, kHeight);
    camera.projection = glm::perspective(0.9, double(kWidth) / kHeight, 0.5, kCameraFar);
    const auto mask = engine::test::renderShadowMask(plugins(), scene, camera, 0);
    const auto control = engine::test::renderShadowMask(plugins(), unlimitedScene, camera, 0);
    const std::vector<int> truth = engine::test::floorTruthImage(
        camera, 0.0, 400.0, [](const glm::dvec3&) { return true; }, engine::test::boxFloorTruth(scene, 0, blocks, 0.0));
    const glm::dvec3 eye = camera.position(), forward = -glm::dvec3(camera.eyeToWorld[2]);
    int beyond = 0, beyondShadowed = 0, controlShadowed = 0, fading = 0, fadingRight = 0;
    for (int y = 1; y + 1 < kHeight; ++y)
        for (int x = 1; x + 1 < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + x;
            if (truth[i] < 0) continue;
            const engine::test::Ray ray = engine::test::pixelRay(camera, x, y);
            const glm::dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            const double depth = glm::dot(p - eye, forward);
            if (depth > kCameraFar * 0.95) continue;
            if (depth > kDistance) {
                ++beyond;
                beyondShadowed += mask[i] < 255;
                controlShadowed += control[i] < 128;
            } else if (depth > kDistance * (1.0 - kFade) && truth[i] == 0 &&
                       !engine::test::nearTruthEdge(truth, kWidth, x, y, 2)) {
                // Shadowed up to the band, lit at its end, linearly in between: within 6 of
                // 255 levels, a pixel's own depth span there and 8-bit rounding.
                const double lit = (depth - kDistance * (1.0 - kFade)) / (kDistance * kFade);
                ++fading;
                fadingRight += std::abs(mask[i] - 255.0 * lit) <= 6.0;
            }
        }
    std::printf("past %.0f m: %d of %d ground pixels shadowed (without the distance: %d); fade band: %d of %d "
                "shadowed pixels at the fade's shade\n",
                kDistance, beyondShadowed, beyond, controlShadowed, fadingRight, fading);
    ASSERT_GT(beyond, 1000);
    ASSERT_GT(controlShadowed, 100);  // the far blocks' shadows (252): the check below can fail
    EXPECT_EQ(beyondShadowed, 0);
    ASSERT_GT(fading, 100);
    // Measured: all of them (643). A hundredth for another CPU's rounding at a texel's edge.
    EXPECT_GE(fadingRight, fading - fading / 100);
}

// cascade_blend with stable cascades: the maps are the same (a stable cascade is not widened
// for the band), so the blended mask equals the hard-switched one on every ground pixel
// outside the bands [split, split + blend * (split - previous split)] and differs inside them.
TEST_F(Cascades, BlendingChangesTheShadeOnlyInTheBandsPastEachSplit) {
    constexpr double kBlend = 0.5;
    const OutdoorScene hard = engine::test::makeOutdoorScene({{"cascades", 4}});
    const OutdoorScene blended = engine::test::makeOutdoorScene({{"cascades", 4}, {"cascade_blend", kBlend}});
    const engine::FrameCamera camera = engine::test::outdoorCamera(kWidth, kHeight);
    engine::FrameResult frame;
    const auto hardMask = engine::test::renderShadowMask(plugins(), hard.scene, camera, hard.sunSlot, &frame);
    const auto blendedMask = engine::test::renderShadowMask(plugins(), blended.scene, camera, blended.sunSlot);
    const std::vector<double> splits = frame.shadowView(hard.sunSlot)->cascadeSplits;
    ASSERT_EQ(splits.size(), 5u);
    const glm::dvec3 eye = camera.position(), forward = -glm::dvec3(camera.eyeToWorld[2]);
    const auto inBand = [&](const glm::dvec3& p) {
        const double depth = glm::dot(p - eye, forward);
        for (std::size_t c = 1; c + 1 < splits.size(); ++c)
            if (depth >= splits[c] && depth <= splits[c] + kBlend * (splits[c] - splits[c - 1])) return true;
        return false;
    };
    // Every ground pixel the camera sees (not behind a post or building), by whether its
    // point lies in a band.
    const auto ground = engine::test::floorTruthImage(camera, 0.0, OutdoorScene::kGroundHalf,
                                                      [](const glm::dvec3&) { return true; },
                                                      engine::test::boxFloorTruth(hard.scene, hard.sunSlot,
                                                                                  hard.occluders, 0.0));
    int outsideDiffering = 0, insideDiffering = 0, outside = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + x;
            if (ground[i] < 0) continue;
            const engine::test::Ray ray = engine::test::pixelRay(camera, x, y);
            const glm::dvec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            const bool differs = hardMask[i] != blendedMask[i];
            if (inBand(p)) insideDiffering += differs;
            else {
                ++outside;
                outsideDiffering += differs;
            }
        }
    std::printf("blend %.1f: %d pixels differ inside the bands, %d of %d outside\n", kBlend, insideDiffering,
                outsideDiffering, outside);
    EXPECT_GT(outside, 10000);
    EXPECT_EQ(outsideDiffering, 0);
    EXPECT_GT(insideDiffering, 0) << "the blend changed nothing";
}

// One renderer over a camera path, so maps can be kept between frames: per frame the sun's
// shadow mask and the sun's shadow view.
struct WalkFrame {
    std::vector<std::uint8_t> mask;
    engine::ShadowView sun;
};

std::vector<WalkFrame> walk(const std::vector<engine::RenderPlugin*>& plugins, const OutdoorScene& outdoor,
                            const std::vector<engine::FrameCamera>& cameras) {
    engine::Renderer renderer({}, plugins);
    renderer.setScene(outdoor.scene);
    std::vector<WalkFrame> frames;
    for (const engine::FrameCamera& camera : cameras) {
        engine::FrameRequest request;
        request.camera = camera;
        request.shadowMaskSlots = {outdoor.sunSlot};
        const engine::FrameResult result = renderer.renderFrame(request);
        frames.push_back({renderer.readShadowMask(outdoor.sunSlot), *result.shadowView(outdoor.sunSlot)});
    }
    return frames;
}

// How many frames after the first re-rendered each cascade (its layer missed the cache).
std::vector<int> cascadeRenders(const std::vector<WalkFrame>& frames) {
    std::vector<int> renders(4, 0);
    for (std::size_t i = 1; i < frames.size(); ++i)
        for (std::size_t c = 0; c < frames[i].sun.layers.size(); ++c) renders[c] += frames[i].sun.layers[c].redrawn;
    return renders;
}

TEST_F(Cascades, StableFarCascadesAreKeptOnASlowWalk) {
    // 2 cm per frame down the street (a slow walk at 60 Hz is about this).
    constexpr int kFrames = 17;
    std::vector<engine::FrameCamera> cameras;
    for (int i = 0; i < kFrames; ++i)
        cameras.push_back(engine::test::outdoorCamera(kWidth, kHeight, {0.0, 0.0, -0.02 * i}));
    const std::vector<int> stable = cascadeRenders(walk(plugins(), engine::test::makeOutdoorScene({{"cascades", 4}}), cameras));
    const std::vector<int> fitted = cascadeRenders(
        walk(plugins(), engine::test::makeOutdoorScene({{"cascades", 4}, {"stable", false}}), cameras));
    std::printf("re-rendered in %d frames: stable %d %d %d %d, fitted %d %d %d %d\n", kFrames - 1, stable[0], stable[1],
                stable[2], stable[3], fitted[0], fitted[1], fitted[2], fitted[3]);
    // Measured on llvmpipe: stable 7, 4, 2, 0 of 16 frames (nearest to farthest), fitted
    // 16 in every cascade. The bound: a stable far cascade re-renders at most one
    // frame in four.
    EXPECT_LE(stable[3], (kFrames - 1) / 4);
    // Fitted cascades follow the camera continuously: every frame re-renders (the control
    // that shows the count above can fail).
    EXPECT_EQ(fitted[3], kFrames - 1);

    // The default (auto) keeps one count over the walk: a count that flipped would
    // re-create the array map and re-render every layer. Each step moves the camera, so each
    // frame weighs the counts again; a frame that repeats the last camera reuses the weighing.
    std::vector<engine::FrameCamera> walkAndStop = cameras;
    walkAndStop.push_back(cameras.back());
    const std::vector<WalkFrame> automatic =
        walk(plugins(), engine::test::makeOutdoorScene(nlohmann::json::object()), walkAndStop);
    const std::size_t count = automatic.front().sun.layers.size();
    ASSERT_GE(count, 1u);
    for (std::size_t i = 0; i < automatic.size(); ++i) {
        EXPECT_EQ(automatic[i].sun.layers.size(), count) << "frame " << i;
        EXPECT_EQ(automatic[i].sun.cascadeCountReused, i + 1 == automatic.size()) << "frame " << i;
    }
    const std::vector<int> renders = cascadeRenders(automatic);
    std::printf("auto: %zu cascades, re-rendered in %d %d %d frames\n", count, renders[0], renders[1], renders[2]);
    EXPECT_LE(renders[count - 1], (kFrames - 1) / 4);
}

// An orthographic camera looking down at the posts, moved sideways by exactly one pixel per
// frame: every world point moves by exactly one pixel, so a pixel's shadow state is compared
// with the same world point's in the next frame without resampling. The truth there does
// not change (a static scene), so every change is shimmer.
double shimmer(const std::vector<engine::RenderPlugin*>& plugins, const nlohmann::json& sun) {
    const OutdoorScene outdoor = engine::test::makeOutdoorScene(sun);
    constexpr double kHalfWidth = 20.0, kPixel = 2.0 * kHalfWidth / kWidth;
    constexpr int kFrames = 9;
    std::vector<engine::FrameCamera> cameras;
    for (int i = 0; i < kFrames; ++i) {
        engine::FrameCamera camera;
        camera.width = kWidth;
        camera.height = kHeight;
        camera.eyeToWorld = engine::test::placeLooking({0, 40, 25}, {0, 0, -15});
        camera.eyeToWorld[3] += camera.eyeToWorld[0] * (kPixel * i);  // along the image's x
        const double halfHeight = kHalfWidth * kHeight / kWidth;
        camera.projection = glm::ortho(-kHalfWidth, kHalfWidth, -halfHeight, halfHeight, 0.1, 200.0);
        cameras.push_back(camera);
    }
    const std::vector<WalkFrame> frames = walk(plugins, outdoor, cameras);
    long changed = 0, evaluated = 0;
    for (int i = 0; i + 1 < kFrames; ++i) {
        const auto truthAt = engine::test::boxFloorTruth(outdoor.scene, outdoor.sunSlot, outdoor.occluders, 0.0);
        const auto everywhere = [](const glm::dvec3&) { return true; };
        const std::vector<int> truth = engine::test::floorTruthImage(cameras[i], 0.0, OutdoorScene::kGroundHalf, everywhere, truthAt);
        const std::vector<int> next = engine::test::floorTruthImage(cameras[i + 1], 0.0, OutdoorScene::kGroundHalf, everywhere, truthAt);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 1; x < kWidth; ++x) {
                // Pixel x of frame i shows the world point of pixel x - 1 of frame i + 1.
                const std::size_t here = std::size_t(y) * kWidth + x, there = here - 1;
                if (truth[here] < 0 || next[there] < 0) continue;
                ++evaluated;
                changed += (frames[i].mask[here] >= 128) != (frames[i + 1].mask[there] >= 128);
            }
    }
    return evaluated ? double(changed) / evaluated : 1.0;
}

TEST_F(Cascades, StableCascadesShimmerLessThanFittedOnes) {
    const double stable = shimmer(plugins(), {{"cascades", 4}});
    const double fitted = shimmer(plugins(), {{"cascades", 4}, {"stable", false}});
    std::printf("shimmer: stable %.4f%%, fitted %.4f%%\n", 100 * stable, 100 * fitted);
    // Measured on llvmpipe: stable 0.0004 %, fitted
    // 0.214 %. Asserted: stable at most a tenth of fitted, a margin of ~50x on the measured
    // ratio, and the fitted path must shimmer at all (> 0.05 %) or the path shows nothing.
    EXPECT_GT(fitted, 0.0005);
    EXPECT_LE(stable, fitted / 10.0);
}

} // namespace
