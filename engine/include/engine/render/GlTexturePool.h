#pragma once
// The render graph's GL allocator: transient textures are pooled by description, so a
// texture released by one pass is reused by the next pass (and frame) that needs the same
// size and format instead of being created again.
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
    std::size_t textureCount() const { return textures_.size(); }

private:
    struct Entry {
        TextureDesc desc;
        gl::Texture texture;
        bool inUse = false;
    };
    std::vector<Entry> textures_;
};

} // namespace engine
