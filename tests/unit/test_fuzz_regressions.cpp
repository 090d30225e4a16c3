// Inputs the glTF fuzzer (tools/fuzz) found crashing or exhausting memory: each must now end
// in one InputError naming the file. tools/fuzz/run.sh replays them under ASan as well.
#include "engine/gltf/GltfLoader.h"
#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <filesystem>

TEST(FuzzRegressions, EveryFoundInputEndsInAClearError) {
    const std::filesystem::path folder = std::filesystem::path(TEST_DATA_DIR) / "fuzz-regressions";
    int replayed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".gltf" && entry.path().extension() != ".glb") continue;
        ++replayed;
        try {
            engine::loadGltf(entry.path());
            ADD_FAILURE() << entry.path() << " loaded";
        } catch (const engine::InputError& error) {
            EXPECT_NE(std::string(error.what()).find(entry.path().filename().string()), std::string::npos)
                << error.what();
        }
    }
    EXPECT_GE(replayed, 3);
}

TEST(FuzzRegressions, MessagesSayWhatIsWrong) {
    const std::filesystem::path folder = std::filesystem::path(TEST_DATA_DIR) / "fuzz-regressions";
    const auto message = [&](const char* file) {
        try {
            engine::loadGltf(folder / file);
        } catch (const engine::InputError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_NE(message("jpeg-dht-more-than-256-codes.gltf").find("more than 256 codes"), std::string::npos);
    EXPECT_NE(message("zero-accessor-huge-count.gltf").find("has no bufferView"), std::string::npos);
}
