#include "engine/gl/Buffer.h"

#include <cassert>

namespace engine::gl {

Buffer Buffer::create(std::size_t bytes, const void* data, GLbitfield storageFlags) {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    Buffer buffer(name, Ownership::Adopt, {bytes});
    glNamedBufferStorage(name, static_cast<GLsizeiptr>(bytes), data, storageFlags);
    return buffer;
}

Buffer Buffer::wrap(GLuint name, Ownership ownership) {
    GLint64 bytes = 0;
    glGetNamedBufferParameteri64v(name, GL_BUFFER_SIZE, &bytes);
    return Buffer(name, ownership, {static_cast<std::size_t>(bytes)});
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    assert(offset + bytes <= size() && "Buffer::update past the end of the buffer");
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                         data);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
    glBindBufferBase(target, index, id());
}

} // namespace engine::gl
