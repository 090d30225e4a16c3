#pragma once
// The render graph's GL allocator: transient textures are pooled by description, so a
// texture released by one pass is reused by the next pass (and frame) that needs the same
// size and format instead of being created again. A texture no frame acquired for
// kIdleFramesBeforeFree frames is deleted at endFrame(): after a settings change (a shadow
// map's resolution or depth format, the output size) the old size's textures go, instead
// of the pool holding one of every description ever used.
#include "engine/gl/Texture.h"
#include "engine/graph/RenderGraph.h"

#include <vector>

namespace engine {

// The GL internal format of a graph texture format.
unsigned internalFormatFor(TextureFormat format);

class GlTexturePool final : public ResourceAllocator {
public:
    std::uint32_t acquire(const TextureDesc& desc) override;
    void release(std::uint32_t handle, const TextureDesc& desc) override;
    // Closes a frame: deletes every texture not in use that no frame acquired during the
    // last kIdleFramesBeforeFree frames (this one included).
    void endFrame();
    std::size_t textureCount() const { return textures_.size(); }

    // Long enough that a description used every frame, or with gaps of a few frames, keeps
    // its texture; short enough that a settings change frees the old textures within a
    // fraction of a second at interactive rates. A texture idle for longer (a woo light's
    // first layer while the light stands still and its map is cached) is made again when
    // needed: an allocation, far less than the pass that fills it.
    static constexpr std::uint64_t kIdleFramesBeforeFree = 8;

private:
    struct Entry {
        TextureDesc desc;
        gl::Texture texture;
        bool inUse = false;
        std::uint64_t lastAcquired = 0;  // frame number (frame_) of the last acquire
    };
    std::vector<Entry> textures_;
    std::uint64_t frame_ = 0;  // frames ended so far
};

} // namespace engine
