// renderer.msaa leaves what is measured alone: the shadow evaluation of every light
// (engine-render --truth, as users and the bench read it) and the masks it scores are the same
// with and without multisampling.
#include "EngineRenderRun.h"

#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

// Masks and truth are single-sampled passes of their own, drawn whatever renderer.msaa says.
TEST(MsaaTruth, ShadowEvaluationAndMasksAreUnchanged) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "engine_msaa_truth";
    fs::create_directories(dir);
    const fs::path scene = fs::path(CONTENT_DIR) / "scenes" / "showcase.gltf";
    // Small enough to trace quickly; every showcase light still has thousands of evaluated pixels.
    constexpr int kWidth = 320, kHeight = 180;
    const std::string light = "sun";
    nlohmann::json stats[2];
    std::vector<std::uint8_t> masks[2], images[2];
    // The repository's config, and the same with renderer.msaa 4 (the later --config wins).
    nlohmann::json multisampled;
    std::ifstream(fs::path(CONTENT_DIR) / "engine.json") >> multisampled;
    multisampled["renderer"]["msaa"] = 4;
    const fs::path multisampledConfig = dir / "engine_msaa4.json";
    std::ofstream(multisampledConfig) << multisampled.dump();
    for (const int i : {0, 1}) {
        const fs::path stem = dir / (i == 0 ? "msaa1" : "msaa4");
        const fs::path mask = stem.string() + "_mask.png";
        stats[i] = engine_render_test::renderWithStats(
            scene, stem, kWidth, kHeight,
            "--truth --shadow-mask '" + light + "=" + mask.string() + "'" +
                (i == 0 ? std::string() : " --config '" + multisampledConfig.string() + "'"));
        masks[i] = engine_render_test::readMask(mask);
        int width = 0, height = 0;
        images[i] = engine::readPng(stem.string() + ".png", 4, width, height);
    }
    ASSERT_TRUE(stats[0].contains("lights") && stats[1].contains("lights")) << stats[0].dump() << stats[1].dump();
    ASSERT_EQ(stats[0]["lights"].size(), stats[1]["lights"].size());
    ASSERT_FALSE(stats[0]["lights"].empty());
    // Exactly equal: the masks are the same single-sampled pass at both settings, scored
    // against the same single-sampled surface capture; any difference would be multisampling
    // leaking into what is measured.
    for (const nlohmann::json& single : stats[0]["lights"]) {
        const nlohmann::json* multi = engine_render_test::lightEntry(stats[1]["lights"], single.value("light", ""));
        ASSERT_NE(multi, nullptr);
        EXPECT_GT(single.value("evaluated_pixels", 0), 0) << single.dump();
        for (const char* key : {"evaluated_pixels", "acne", "leak", "error", "error_noedge"}) {
            ASSERT_TRUE(single.contains(key)) << key << " missing: " << single.dump();
            EXPECT_EQ(single[key], (*multi)[key]) << single.value("light", "") << " " << key;
        }
    }
    EXPECT_EQ(masks[0], masks[1]);
    // ...while the shaded images do differ (at the edges): the setting took effect.
    EXPECT_NE(images[0], images[1]);
    // Away from edges, shadows included, the two images agree: where a pixel's 3x3
    // neighbourhood at msaa 1 lies within kSmooth of it (no geometry edge crosses it), the
    // multisampled pixel is the same shade.
    constexpr int kSmooth = 2;
    const auto channel = [&](int image, int x, int y, int c) { return int(images[image][(y * kWidth + x) * 4 + c]); };
    int smooth = 0, worst = 0, differing = 0;
    for (int y = 1; y + 1 < kHeight; ++y)
        for (int x = 1; x + 1 < kWidth; ++x) {
            bool flat = true;
            for (int dy = -1; dy <= 1 && flat; ++dy)
                for (int dx = -1; dx <= 1 && flat; ++dx)
                    for (int c = 0; c < 3; ++c)
                        flat = flat && std::abs(channel(0, x + dx, y + dy, c) - channel(0, x, y, c)) <= kSmooth;
            int difference = 0;
            for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(channel(0, x, y, c) - channel(1, x, y, c)));
            differing += difference > 0;
            if (!flat) continue;
            ++smooth;
            worst = std::max(worst, difference);
        }
    std::printf("msaa 4 vs 1: %d pixels differ of %d; %d smooth ones, largest difference there %d / 255\n", differing,
                kWidth * kHeight, smooth, worst);
    EXPECT_GT(smooth, kWidth * kHeight / 2);  // measured 45686 of 57600: most of the picture
    // A smooth pixel may still hold an edge between surfaces whose shades differ by at most
    // kSmooth (its neighbours' centres see both), which four samples blend: at most kSmooth
    // from the single-sampled value (measured: 1). A shade changed by multisampling (per-sample
    // shadow lookups, a lost shade term) would move whole regions by far more.
    EXPECT_LE(worst, kSmooth);
}

// engine-render --msaa N replaces the config's renderer.msaa: the same image as the config
// asking for it; a count outside 1, 2, 4, 8 is refused in one line naming the flag.
TEST(MsaaTruth, MsaaFlagReplacesTheConfigsSetting) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "engine_msaa_flag";
    fs::create_directories(dir);
    const fs::path scene = fs::path(CONTENT_DIR) / "scenes" / "showcase.gltf";
    constexpr int kWidth = 160, kHeight = 90;
    nlohmann::json multisampled;
    std::ifstream(fs::path(CONTENT_DIR) / "engine.json") >> multisampled;
    multisampled["renderer"]["msaa"] = 4;
    const fs::path multisampledConfig = dir / "engine_msaa4.json";
    std::ofstream(multisampledConfig) << multisampled.dump();
    engine_render_test::renderWithStats(scene, dir / "config", kWidth, kHeight,
                                        "--config '" + multisampledConfig.string() + "'");
    engine_render_test::renderWithStats(scene, dir / "flag", kWidth, kHeight, "--msaa 4");
    engine_render_test::renderWithStats(scene, dir / "single", kWidth, kHeight, "--msaa 1");
    int width = 0, height = 0;
    const std::vector<std::uint8_t> config = engine::readPng(dir / "config.png", 4, width, height);
    EXPECT_EQ(engine::readPng(dir / "flag.png", 4, width, height), config);
    EXPECT_NE(engine::readPng(dir / "single.png", 4, width, height), config);
    for (const char* samples : {"3", "16", "0", "four"}) {
        const fs::path log = dir / "refused.log";
        const int status = engine_render_test::runQuietly(std::string(ENGINE_RENDER_BIN) + " --scene '" + scene.string() +
                                                              "' --out '" + (dir / "refused.png").string() + "' --msaa " +
                                                              samples,
                                                          log);
        std::ifstream in(log);
        const std::string message((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(status, 1) << samples << ": " << message;
        EXPECT_NE(message.find("--msaa"), std::string::npos) << message;
    }
}

} // namespace
