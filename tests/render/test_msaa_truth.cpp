// renderer.msaa leaves what is measured alone: the shadow evaluation of every light
// (engine-render --truth, as users and the bench read it) and the masks it scores are the same
// with and without multisampling.
#include "EngineRenderRun.h"

#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
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
}

} // namespace
