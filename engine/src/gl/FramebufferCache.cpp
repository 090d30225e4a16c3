#include "engine/gl/FramebufferCache.h"

#include <algorithm>

namespace engine::gl {

namespace {

// Every cache alive on this thread's contexts. GL objects are used from one thread, like
// the caches themselves.
std::vector<FramebufferCache*>& liveCaches() {
    static std::vector<FramebufferCache*> caches;
    return caches;
}

// More target sets than any frame uses means targets keep being replaced without their
// textures dying (e.g. a pool cycling through many sizes): start over rather than grow.
constexpr std::size_t kMaxEntries = 256;

} // namespace

FramebufferCache::FramebufferCache() { liveCaches().push_back(this); }

FramebufferCache::~FramebufferCache() { std::erase(liveCaches(), this); }

const Framebuffer& FramebufferCache::get(const std::vector<TargetAttachment>& attachments,
                                         const std::string& what) {
    for (const Entry& entry : entries_)
        if (entry.attachments == attachments) return entry.framebuffer;
    if (entries_.size() >= kMaxEntries) entries_.clear();

    Framebuffer framebuffer = Framebuffer::create();
    std::vector<GLenum> drawBuffers;
    for (const TargetAttachment& attachment : attachments) {
        if (attachment.layer < 0)
            glNamedFramebufferTexture(framebuffer.id(), attachment.point, attachment.texture, 0);
        else
            glNamedFramebufferTextureLayer(framebuffer.id(), attachment.point, attachment.texture, 0,
                                           attachment.layer);
        if (attachment.point != GL_DEPTH_ATTACHMENT) drawBuffers.push_back(attachment.point);
    }
    if (drawBuffers.empty()) {
        glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
        glNamedFramebufferReadBuffer(framebuffer.id(), GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(framebuffer.id(), static_cast<GLsizei>(drawBuffers.size()),
                                      drawBuffers.data());
    }
    framebuffer.requireComplete(what);
    ++created_;
    entries_.push_back({attachments, std::move(framebuffer)});
    return entries_.back().framebuffer;
}

void forgetTextureInFramebufferCaches(GLuint texture) noexcept {
    for (FramebufferCache* cache : liveCaches())
        std::erase_if(cache->entries_, [texture](const FramebufferCache::Entry& entry) {
            return std::any_of(entry.attachments.begin(), entry.attachments.end(),
                               [texture](const TargetAttachment& a) { return a.texture == texture; });
        });
}

} // namespace engine::gl
