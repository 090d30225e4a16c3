// Outputs (engine/util/OutputFile.h): checked before the work that makes them, written
// whole or not at all, and never in place of a file the user made read-only.
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("output_file_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    static std::string contents(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    // The message checkOutputPath (and writeFileAtomically) gives for `path`, "" if none.
    static std::string refusal(const fs::path& path) {
        try {
            engine::checkOutputPath(path);
        } catch (const engine::InputError& error) {
            return error.what();
        }
        return "";
    }
    fs::path dir_;
};

TEST_F(OutputFile, ANewFileOrAWritableOneIsAccepted) {
    EXPECT_EQ(refusal(dir_ / "new.png"), "");
    engine::writeFileAtomically(dir_ / "new.png", "first");
    EXPECT_EQ(refusal(dir_ / "new.png"), "");
    engine::writeFileAtomically(dir_ / "new.png", "second");
    EXPECT_EQ(contents(dir_ / "new.png"), "second");
}

TEST_F(OutputFile, AMissingFolderIsNamed) {
    const std::string message = refusal(dir_ / "missing" / "out.png");
    EXPECT_NE(message.find("out.png"), std::string::npos) << message;
    EXPECT_NE(message.find("its folder " + (dir_ / "missing").string() + " does not exist"), std::string::npos)
        << message;
}

TEST_F(OutputFile, AFolderIsNotAFile) {
    fs::create_directories(dir_ / "images");
    EXPECT_NE(refusal(dir_ / "images").find("is a folder, not a file to write"), std::string::npos);
}

// As cp refuses it, even for root (whom the permission bits do not stop): the user marked the
// file as not to be changed.
TEST_F(OutputFile, AReadOnlyFileIsRefusedAndKept) {
    const fs::path kept = dir_ / "kept.png";
    engine::writeFileAtomically(kept, "precious");
    fs::permissions(kept, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    EXPECT_NE(refusal(kept).find("the file exists and is read-only: not replaced"), std::string::npos) << refusal(kept);
    EXPECT_THROW(engine::writeFileAtomically(kept, "replaced"), engine::InputError);
    EXPECT_EQ(contents(kept), "precious");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << "no temporary left";
}

} // namespace
