#include "engine/gl/LiveObjects.h"

#include <atomic>
#include <cassert>

namespace engine::gl {

namespace {

// Atomic so that owners dying on another thread's context (a loader thread, a test's second
// context) keep the sums right; relaxed because a reader only needs each count's own value.
struct Counters {
    std::atomic<std::int64_t> textures{0}, framebuffers{0}, buffers{0}, programs{0}, shaders{0},
        samplers{0}, vertexArrays{0}, queries{0};
};

Counters& counters() {
    static Counters instance;
    return instance;
}

} // namespace

LiveObjectCounts liveObjectCounts() noexcept {
    const Counters& c = counters();
    constexpr auto order = std::memory_order_relaxed;
    return {c.textures.load(order),  c.framebuffers.load(order), c.buffers.load(order),
            c.programs.load(order),  c.shaders.load(order),      c.samplers.load(order),
            c.vertexArrays.load(order), c.queries.load(order)};
}

namespace detail {

void countOwnedObjects(GLenum labelNamespace, int delta) noexcept {
    Counters& c = counters();
    std::atomic<std::int64_t>* counter = nullptr;
    switch (labelNamespace) {
    case GL_TEXTURE: counter = &c.textures; break;
    case GL_FRAMEBUFFER: counter = &c.framebuffers; break;
    case GL_BUFFER: counter = &c.buffers; break;
    case GL_PROGRAM: counter = &c.programs; break;
    case GL_SHADER: counter = &c.shaders; break;
    case GL_SAMPLER: counter = &c.samplers; break;
    case GL_VERTEX_ARRAY: counter = &c.vertexArrays; break;
    case GL_QUERY: counter = &c.queries; break;
    }
    assert(counter && "an owner of a GL object kind LiveObjects does not count");
    if (counter) counter->fetch_add(delta, std::memory_order_relaxed);
}

} // namespace detail

} // namespace engine::gl
