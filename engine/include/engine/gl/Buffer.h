#pragma once
// Buffer: an immutable-storage GL buffer (glCreateBuffers + glNamedBufferStorage).
// Its size is fixed at creation; contents change through update() when created with
// GL_DYNAMIC_STORAGE_BIT (or by GPU writes).
#include "engine/gl/Handle.h"

#include <cstddef>

namespace engine::gl {

namespace detail {
struct BufferTraits {
    static constexpr GLenum labelNamespace = GL_BUFFER;
    static void destroy(GLuint name) noexcept { glDeleteBuffers(1, &name); }
};
struct BufferInfo {
    std::size_t bytes = 0;
};
} // namespace detail

class Buffer : public Handle<detail::BufferTraits, detail::BufferInfo> {
public:
    Buffer() = default;

    // data may be null (uninitialised storage). storageFlags: GL_DYNAMIC_STORAGE_BIT to
    // allow update(), GL_MAP_*_BIT to allow mapping; 0 = written once, here.
    static Buffer create(std::size_t bytes, const void* data, GLbitfield storageFlags = 0);

    // Takes a buffer created elsewhere; its size is queried from GL.
    static Buffer wrap(GLuint name, Ownership ownership = Ownership::Adopt);

    // glNamedBufferSubData; needs GL_DYNAMIC_STORAGE_BIT. The range must lie inside size().
    void update(std::size_t offset, std::size_t bytes, const void* data);

    // Binds to an indexed target (GL_UNIFORM_BUFFER, GL_SHADER_STORAGE_BUFFER, ...).
    void bindBase(GLenum target, GLuint index) const;

    std::size_t size() const { return info().bytes; }

private:
    using Handle::Handle;
};

} // namespace engine::gl
