#pragma once
// Where the render graph gets physical textures. The engine implements it with GL (pooling
// by desc, so a texture released by one pass is handed to the next transient of that desc);
// unit tests use a fake that records the calls. Keeping this an interface is what keeps the
// graph core free of GL.
#include "engine/graph/TextureDesc.h"

#include <cstdint>

namespace engine {

struct ResourceAllocator {
    virtual ~ResourceAllocator() = default;
    // A physical handle (a GL texture name in practice) matching desc, valid until released.
    virtual std::uint32_t acquire(const TextureDesc& desc) = 0;
    // Gives back a handle from acquire(); the allocator may hand it out again right away.
    virtual void release(std::uint32_t handle, const TextureDesc& desc) = 0;
};

} // namespace engine
