// The record a tool keeps in a scene's asset.extras (tools/common/AssetExtras.h): set in place
// with every other byte kept, replaced when set again, read back from .gltf and .glb, and
// what cannot take it refused.
#include "AssetExtras.h"
#include "SceneContainers.h"

#include "engine/util/Error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

const nlohmann::json kTuned = tools::tunedSizeRecord({640, 360});

std::string withRecord(const std::string& text) {
    return tools::setAssetExtras(text, {{tools::kTunedForKey, kTuned}}, "test.gltf");
}

TEST(AssetExtras, AreAddedWhereTheAssetHasNoneAndEveryOtherByteStays) {
    const std::string text = R"({ "asset" : { "version" : "2.0" },  "nodes" : [ {"name": "a"} ] })";
    const std::string out = withRecord(text);
    const nlohmann::json document = nlohmann::json::parse(out);
    EXPECT_EQ(document["asset"]["extras"][tools::kTunedForKey], kTuned);
    EXPECT_EQ(document["asset"]["version"], "2.0");
    // The text up to the end of the asset's last member, and all after the asset, as it was.
    const std::size_t versionEnd = text.find("\"2.0\"") + 5;
    EXPECT_EQ(out.substr(0, versionEnd), text.substr(0, versionEnd));
    EXPECT_EQ(out.substr(out.find(" }, ")), text.substr(text.find(" }, ")));
}

TEST(AssetExtras, ReplaceTheirMemberAndKeepTheOthers) {
    const std::string text =
        R"({"asset":{"version":"2.0","extras":{"author":"me","shadowmap_tune":{"width":1,"height":1}}}})";
    const nlohmann::json document = nlohmann::json::parse(withRecord(text));
    EXPECT_EQ(document["asset"]["extras"][tools::kTunedForKey], kTuned);
    EXPECT_EQ(document["asset"]["extras"]["author"], "me");
    // Setting the same value again writes the same bytes (tuning a tuned file changes nothing).
    EXPECT_EQ(withRecord(withRecord(text)), withRecord(text));
}

TEST(AssetExtras, ThatAreNotAnObjectAreRefusedNamingTheFile) {
    try {
        withRecord(R"({"asset":{"version":"2.0","extras":7}})");
        FAIL() << "accepted extras that are not an object";
    } catch (const engine::InputError& error) {
        EXPECT_NE(std::string(error.what()).find("test.gltf"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("asset.extras"), std::string::npos) << error.what();
    }
}

TEST(AssetExtras, TunedSizeIsReadFromGltfAndGlbAndIgnoredWhenMalformed) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "asset_extras_test";
    std::filesystem::create_directories(folder);
    const std::string text = withRecord(R"({"asset":{"version":"2.0"}})");
    std::ofstream(folder / "a.gltf", std::ios::binary) << text;
    std::ofstream(folder / "a.glb", std::ios::binary) << tools::joinGlb(text, "");
    for (const char* name : {"a.gltf", "a.glb"}) {
        const auto size = tools::readTunedSize(folder / name);
        ASSERT_TRUE(size) << name;
        EXPECT_EQ(size->width, 640);
        EXPECT_EQ(size->height, 360);
    }
    EXPECT_FALSE(tools::readTunedSize(folder / "missing.gltf"));
    EXPECT_FALSE(tools::tunedSize(nlohmann::json::parse(R"({"asset":{"extras":{"shadowmap_tune":{"width":-1,"height":9}}}})")));
    EXPECT_FALSE(tools::tunedSize(nlohmann::json::parse(R"({"asset":{"extras":{"shadowmap_tune":{"width":"640","height":9}}}})")));
    std::filesystem::remove_all(folder);
}

TEST(AssetExtras, APictureIsFarFromTheTunedSizeBeyondTwiceOrHalfItsPixels) {
    const tools::TunedSize tuned{1280, 720};
    EXPECT_FALSE(tools::farFromTunedSize(tuned, 1280, 720));
    EXPECT_FALSE(tools::farFromTunedSize(tuned, 1280, 1440));  // twice the pixels
    EXPECT_FALSE(tools::farFromTunedSize(tuned, 640, 720));    // half
    EXPECT_TRUE(tools::farFromTunedSize(tuned, 1920, 1080));   // 2.25 times
    EXPECT_TRUE(tools::farFromTunedSize(tuned, 320, 240));     // a twelfth
}

} // namespace
