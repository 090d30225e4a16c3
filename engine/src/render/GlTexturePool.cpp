#include "engine/render/GlTexturePool.h"

#include <cassert>

namespace engine {

unsigned internalFormatFor(TextureFormat format) {
    switch (format) {
    case TextureFormat::RGBA8: return GL_RGBA8;
    case TextureFormat::SRGB8_A8: return GL_SRGB8_ALPHA8;
    case TextureFormat::RGBA16F: return GL_RGBA16F;
    case TextureFormat::RGBA32F: return GL_RGBA32F;
    case TextureFormat::R8: return GL_R8;
    case TextureFormat::R32F: return GL_R32F;
    case TextureFormat::RG32F: return GL_RG32F;
    case TextureFormat::Depth16: return GL_DEPTH_COMPONENT16;
    case TextureFormat::Depth24: return GL_DEPTH_COMPONENT24;
    case TextureFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
    }
    return GL_RGBA8;
}

std::uint32_t GlTexturePool::acquire(const TextureDesc& desc) {
    for (Entry& entry : textures_)
        if (!entry.inUse && entry.desc == desc) {
            entry.inUse = true;
            entry.lastAcquired = frame_;
            return entry.texture.id();
        }
    const GLenum format = internalFormatFor(desc.format);
    if (desc.samples > 1) {
        // A multisampled target is only drawn into and resolved: it has no sampler state to set.
        textures_.push_back({desc, gl::Texture::create2DMultisample(format, desc.width, desc.height, desc.samples),
                             true, frame_});
        return textures_.back().texture.id();
    }
    Entry entry{desc,
                desc.cube        ? gl::Texture::createCube(format, desc.width)
                : desc.layers > 1 || desc.array ? gl::Texture::create2DArray(format, desc.width, desc.height, desc.layers)
                                  : gl::Texture::create2D(format, desc.width, desc.height),
                true, frame_};
    // Complete for sampling without mipmaps; shadow lookups override this with samplers.
    entry.texture.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    entry.texture.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    entry.texture.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    entry.texture.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const std::uint32_t id = entry.texture.id();
    textures_.push_back(std::move(entry));
    return id;
}

void GlTexturePool::release(std::uint32_t handle, const TextureDesc& desc) {
    for (Entry& entry : textures_)
        if (entry.texture.id() == handle) {
            assert(entry.inUse && entry.desc == desc);
            entry.inUse = false;
            return;
        }
    assert(false && "released a texture the pool does not own");
}

void GlTexturePool::endFrame() {
    // Deleting a texture also drops the framebuffers that attach it (gl::Texture's deleter,
    // FramebufferCache.h), so the framebuffer caches shrink with the pool.
    std::erase_if(textures_, [this](const Entry& entry) {
        return !entry.inUse && frame_ - entry.lastAcquired >= kIdleFramesBeforeFree;
    });
    ++frame_;
}

} // namespace engine
