// The live-object counts (LiveObjects.h) follow ownership exactly: +1 when an owner takes a
// name it will delete, unchanged by moves and by borrowed names, -1 on deletion or release().
#include "GlTestContext.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/LiveObjects.h"
#include "engine/gl/Texture.h"

namespace engine::gl {
namespace {

using LiveObjectsTest = test::GlTest;

TEST_F(LiveObjectsTest, CountsFollowOwnershipNotNames) {
    const LiveObjectCounts before = liveObjectCounts();
    {
        Texture texture = Texture::create2D(GL_RGBA8, 4, 4);
        Buffer buffer = Buffer::create(16, nullptr);
        EXPECT_EQ(liveObjectCounts().textures, before.textures + 1);
        EXPECT_EQ(liveObjectCounts().buffers, before.buffers + 1);
        EXPECT_EQ(liveObjectCounts().total(), before.total() + 2);

        Texture moved = std::move(texture);  // one object, one count
        EXPECT_EQ(liveObjectCounts().textures, before.textures + 1);

        {
            const Texture borrowed = Texture::wrap(moved.id(), Ownership::Borrow);
            EXPECT_EQ(liveObjectCounts().textures, before.textures + 1);
        }

        const GLuint name = moved.release();  // ours to delete now, not the owners'
        EXPECT_EQ(liveObjectCounts().textures, before.textures);
        const Texture adopted = Texture::wrap(name, Ownership::Adopt);
        EXPECT_EQ(liveObjectCounts().textures, before.textures + 1);
    }
    const LiveObjectCounts after = liveObjectCounts();
    EXPECT_EQ(after.textures, before.textures);
    EXPECT_EQ(after.buffers, before.buffers);
    EXPECT_EQ(after.total(), before.total());
}

} // namespace
} // namespace engine::gl
