// The shadow of a compressed glTF matches the uncompressed file's: engine-render's shadow
// mask of Debian's 2CylinderEngine (plain GLB), its Draco twin (assimp-testmodels) and a
// gltfpack -cc copy (meshopt + 14-bit quantized positions, made here), lit by the same
// --key-light spot (placed, like the framing camera, from the scene's bounds). Quantization
// moves vertices by up to 0.11 (Draco) and 0.04 (gltfpack) units on a 745-unit model, so
// pixels on shadow and silhouette edges may flip; the counts are bounded by what was
// measured plus a margin.
#include "EngineRenderRun.h"
#include "../support/AssimpTestModels.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace {

using namespace engine_render_test;
namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120;

fs::path plainEngine() { return engine::test::kAssimpGltf2Models / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb"; }

class CompressedGltfShadowMask : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("compressed_shadow_mask_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // The key spot light's shadow mask of `scene` (255 lit, 0 shadowed), kWidth x kHeight.
    std::vector<std::uint8_t> shadowMask(const fs::path& scene, const std::string& name) {
        const fs::path mask = dir_ / (name + "_mask.png");
        const std::string command = std::string(ENGINE_RENDER_BIN) + " --config " + CONTENT_DIR + "/engine.json --scene '" +
                                    scene.string() + "' --out '" + (dir_ / (name + ".png")).string() + "' --width " +
                                    std::to_string(kWidth) + " --height " + std::to_string(kHeight) +
                                    " --key-light spot --shadow-mask key_light='" + mask.string() + "'";
        EXPECT_EQ(runQuietly(command), 0) << command;
        int width = 0, height = 0;
        std::vector<std::uint8_t> pixels = engine::readPng(mask, 1, width, height);
        EXPECT_EQ(width, kWidth);
        EXPECT_EQ(height, kHeight);
        return pixels;
    }

    static int litPixels(const std::vector<std::uint8_t>& mask) {
        int count = 0;
        for (std::uint8_t value : mask) count += value > 127;
        return count;
    }

    fs::path dir_;
};

TEST_F(CompressedGltfShadowMask, DracoAndMeshoptShadowLikeThePlainFile) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    const fs::path packed = dir_ / "packed.glb";
    ASSERT_EQ(runQuietly("gltfpack -i '" + plainEngine().string() + "' -o '" + packed.string() + "' -cc"), 0);

    const auto plain = shadowMask(plainEngine(), "plain");
    const auto draco = shadowMask(engine::test::kAssimpGltf2Models / "draco/2CylinderEngine.gltf", "draco");
    const auto meshopt = shadowMask(packed, "meshopt");
    ASSERT_EQ(plain.size(), std::size_t{kWidth} * kHeight);
    const int dracoDiff = differingPixels(plain, draco), meshoptDiff = differingPixels(plain, meshopt);
    std::printf("lit pixels: plain %d; differing from plain: Draco %d, meshopt %d (of %d)\n", litPixels(plain),
                dracoDiff, meshoptDiff, kWidth * kHeight);
    // The engine must fill a good part of the image (measured: 7059 lit of 19200; the
    // background and the shadowed parts are 0), or equal masks would prove nothing.
    EXPECT_GT(litPixels(plain), kWidth * kHeight / 4);
    // Measured with Mesa llvmpipe 22.3: Draco 73, meshopt 163 differing pixels (0.4 % and
    // 0.85 %), on shadow and silhouette edges. The meshopt copy differs more because gltfpack
    // drops the plain file's unused vertices: its bounds are up to 23 units smaller, so the
    // framing camera and the key light sit slightly elsewhere. Bounds: measured + 50 % for
    // edge pixels another rasterizer may round the other way.
    EXPECT_LE(dracoDiff, 110);
    EXPECT_LE(meshoptDiff, 245);
}

} // namespace
