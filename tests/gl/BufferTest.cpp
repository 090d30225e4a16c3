#include "GlTestContext.h"

#include "engine/gl/Buffer.h"

#include <array>
#include <numeric>

namespace engine::gl {
namespace {

using BufferTest = test::GlTest;

std::array<float, 8> readBack(const Buffer& buffer) {
    std::array<float, 8> contents{};
    glGetNamedBufferSubData(buffer.id(), 0, sizeof contents, contents.data());
    return contents;
}

TEST_F(BufferTest, CreateStoresTheDataGiven) {
    std::array<float, 8> data{};
    std::iota(data.begin(), data.end(), 1.0f);
    const Buffer buffer = Buffer::create(sizeof data, data.data());
    EXPECT_EQ(buffer.size(), sizeof data);
    EXPECT_EQ(readBack(buffer), data);
}

TEST_F(BufferTest, UpdateReplacesOnlyTheRangeGiven) {
    std::array<float, 8> data{};
    std::iota(data.begin(), data.end(), 1.0f);
    Buffer buffer = Buffer::create(sizeof data, data.data(), GL_DYNAMIC_STORAGE_BIT);

    const std::array<float, 2> patch{-1.0f, -2.0f};
    buffer.update(3 * sizeof(float), sizeof patch, patch.data());

    const std::array<float, 8> expected{1, 2, 3, -1, -2, 6, 7, 8};
    EXPECT_EQ(readBack(buffer), expected);
}

TEST_F(BufferTest, UpdateWithoutDynamicStorageIsAGlError) {
    // Immutable storage created without GL_DYNAMIC_STORAGE_BIT refuses glNamedBufferSubData:
    // the flag matters, and checkGlError reports it by name.
    const float value = 1.0f;
    Buffer buffer = Buffer::create(sizeof value, &value);
    testing::internal::CaptureStderr(); // the debug context also prints it; keep logs quiet
    buffer.update(0, sizeof value, &value);
    testing::internal::GetCapturedStderr();
    try {
        checkGlError("Buffer::update");
        FAIL() << "no GL error";
    } catch (const GlError& error) {
        EXPECT_STREQ(error.what(), "GL error GL_INVALID_OPERATION at Buffer::update");
    }
}

} // namespace
} // namespace engine::gl
