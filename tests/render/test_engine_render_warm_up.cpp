// engine-render's warm-up for motion: with --orbit-camera or --orbit-light (or an
// animation) no timed frame waits for the shader compiler. Counted, not timed: each frame's
// programs_linked in --stats is 0 (a program linked after warm-up is a 0.3-1.5 s frame on
// llvmpipe), and the tool says so when one is not.
#include "EngineRenderRun.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Motion {
    const char* name;
    const char* scene;
    const char* flags;
};

class EngineRenderWarmUp : public ::testing::TestWithParam<Motion> {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("engine_render_warm_up_" + std::string(GetParam().name));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_P(EngineRenderWarmUp, NoTimedFrameLinksAProgram) {
    const fs::path scene = fs::path(CONTENT_DIR) / "scenes" / (std::string(GetParam().scene) + ".gltf");
    // 24 frames of 2 degrees: past the first moving frames (frame 1 computes and stores the
    // moved shades, frame 2 is the first that evaluates without storing) and into views whose
    // light-footprint split differs.
    const nlohmann::json stats = engine_render_test::renderWithStats(scene, dir_ / "orbit", 160, 90,
                                                                     std::string("--frames 24 ") + GetParam().flags);
    ASSERT_TRUE(stats.contains("programs_linked")) << stats.dump();
    ASSERT_EQ(stats["programs_linked"].size(), 24u);
    for (std::size_t frame = 0; frame < 24; ++frame)
        EXPECT_EQ(stats["programs_linked"][frame], 0) << "timed frame " << frame;
}

INSTANTIATE_TEST_SUITE_P(Orbits, EngineRenderWarmUp,
                         ::testing::Values(Motion{"showcase_camera", "showcase", "--orbit-camera"},
                                           Motion{"lamps_camera", "lamps", "--orbit-camera"},
                                           Motion{"showcase_sun", "showcase", "--orbit-light sun"},
                                           Motion{"lamps_lamp", "lamps", "--orbit-light lamp_1"}),
                         [](const ::testing::TestParamInfo<Motion>& info) { return std::string(info.param.name); });

TEST(EngineRenderWarmUpCold, AColdStartSaysHowManyProgramsItLinked) {
    // --warmup 0 times the cold start: its first frame links every program, and the tool
    // says so beside the frame times.
    const engine_render_test::CommandResult result = engine_render_test::runEngineRender(
        "--config " + std::string(CONTENT_DIR) + "/engine.json --scene " + CONTENT_DIR +
        "/scenes/showcase.gltf --out " + (fs::temp_directory_path() / "engine_render_cold_start.png").string() +
        " --width 64 --height 36 --warmup 0 --frames 2");
    fs::remove(fs::temp_directory_path() / "engine_render_cold_start.png");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("shader programs: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(" linked after warm-up, in "), std::string::npos) << result.output;
}

} // namespace
