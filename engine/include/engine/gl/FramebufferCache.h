#pragma once
// Framebuffers made once per set of render targets and reused every frame, instead of a
// glCreateFramebuffers, attachment calls and a completeness check per pass and cube face
// per frame.
//
// Keyed by the attachments' texture names and layers. GL recycles texture names, and a
// framebuffer keeps a deleted texture's storage attached rather than following its name, so
// a cached framebuffer must never outlive a texture it attaches: gl::Texture's deleter calls
// forgetTextureInFramebufferCaches (Texture.h), which drops those framebuffers from every
// live cache. Textures deleted
// behind gl::Texture's back (raw glDeleteTextures) are not seen: don't.
#include "engine/gl/Framebuffer.h"
#include "engine/gl/Texture.h"

#include <cstddef>
#include <string>
#include <vector>

namespace engine::gl {

struct TargetAttachment {
    GLenum point = GL_NONE;  // GL_COLOR_ATTACHMENTi or GL_DEPTH_ATTACHMENT
    GLuint texture = 0;
    int layer = -1;  // a cube face or array layer; -1: the whole texture
    bool operator==(const TargetAttachment&) const = default;
};

class FramebufferCache {
public:
    FramebufferCache();
    ~FramebufferCache();
    FramebufferCache(const FramebufferCache&) = delete;
    FramebufferCache& operator=(const FramebufferCache&) = delete;

    // The framebuffer with exactly these attachments (level 0). It draws to its colour
    // attachments in the order given, or to none (a depth-only target such as a shadow
    // map). Made and checked complete on first use; `what` names it in that error.
    const Framebuffer& get(const std::vector<TargetAttachment>& attachments, const std::string& what);

    std::size_t size() const { return entries_.size(); }
    // Framebuffers made since construction (a reused one is not counted again).
    std::size_t created() const { return created_; }

private:
    friend void forgetTextureInFramebufferCaches(GLuint texture) noexcept;

    struct Entry {
        std::vector<TargetAttachment> attachments;
        Framebuffer framebuffer;
    };
    // Linear search: a renderer holds a handful (a map per light and face, the lit targets).
    std::vector<Entry> entries_;
    std::size_t created_ = 0;
};

} // namespace engine::gl
