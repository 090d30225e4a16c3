// The render graph's texture pool (GlTexturePool.h): a released texture is handed out again
// for the same description, and deleted once no frame acquired it for
// kIdleFramesBeforeFree frames, not one frame sooner.
#include "GlTestContext.h"

#include "engine/gl/LiveObjects.h"
#include "engine/render/GlTexturePool.h"

namespace engine {
namespace {

using GlTexturePoolTest = test::GlTest;

TEST_F(GlTexturePoolTest, ReusesByDescriptionAndFreesAfterTheIdleFrames) {
    const std::int64_t texturesBefore = gl::liveObjectCounts().textures;
    GlTexturePool pool;
    const TextureDesc desc{64, 64, TextureFormat::Depth24, 1, false};
    const std::uint32_t first = pool.acquire(desc);
    pool.release(first, desc);
    pool.endFrame();  // frame 0: acquired this frame

    const std::uint32_t again = pool.acquire(desc);
    EXPECT_EQ(again, first) << "a released texture of the same description is reused";
    pool.release(again, desc);
    pool.endFrame();  // frame 1: the last acquire

    // Idle frames 2 .. 8: within kIdleFramesBeforeFree of frame 1 until frame 9 ends.
    for (std::uint64_t frame = 2; frame < 1 + GlTexturePool::kIdleFramesBeforeFree; ++frame) {
        pool.endFrame();
        EXPECT_EQ(pool.textureCount(), 1u) << "freed too early, at the end of frame " << frame;
    }
    EXPECT_EQ(gl::liveObjectCounts().textures, texturesBefore + 1);
    pool.endFrame();  // frame 9: 8 frames without an acquire
    EXPECT_EQ(pool.textureCount(), 0u);
    EXPECT_EQ(gl::liveObjectCounts().textures, texturesBefore) << "the GL texture itself is deleted";
}

TEST_F(GlTexturePoolTest, ATextureInUseIsNeverFreed) {
    GlTexturePool pool;
    const TextureDesc desc{32, 32, TextureFormat::RGBA8, 1, false};
    const std::uint32_t held = pool.acquire(desc);
    for (std::uint64_t frame = 0; frame < 3 * GlTexturePool::kIdleFramesBeforeFree; ++frame) pool.endFrame();
    EXPECT_EQ(pool.textureCount(), 1u);
    pool.release(held, desc);
}

} // namespace
} // namespace engine
