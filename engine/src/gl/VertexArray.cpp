#include "engine/gl/VertexArray.h"

#include "engine/gl/Buffer.h"

#include <cassert>

namespace engine::gl {

namespace {

GLsizei bytesOf(GLenum type) {
    switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_HALF_FLOAT: return 2;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_FIXED: return 4;
    case GL_DOUBLE: return 8;
    default: assert(!"VertexArray: packed or unknown attribute type needs an explicit stride");
             return 0;
    }
}

} // namespace

VertexArray VertexArray::create() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArray(name, Ownership::Adopt, {});
}

VertexArray VertexArray::wrap(GLuint name, Ownership ownership) {
    return VertexArray(name, ownership, {});
}

void VertexArray::attribute(GLuint index, const Buffer& buffer, GLint components, GLenum type,
                            GLsizei stride, GLuint offset, bool normalized) {
    // Unlike glVertexAttribPointer, a binding's stride of 0 really means 0 (every vertex
    // reads the same element), so "tightly packed" has to be spelled out here.
    if (stride == 0) stride = components * bytesOf(type);
    // The offset goes on the binding, not the attribute format: a format's relative offset
    // is capped (GL_MAX_VERTEX_ATTRIB_RELATIVE_OFFSET, 2047 minimum), a binding's is not.
    glVertexArrayVertexBuffer(id(), index, buffer.id(), offset, stride);
    glVertexArrayAttribFormat(id(), index, components, type, normalized ? GL_TRUE : GL_FALSE, 0);
    glVertexArrayAttribBinding(id(), index, index);
    glEnableVertexArrayAttrib(id(), index);
}

void VertexArray::elementBuffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(id(), buffer.id());
}

void VertexArray::bind() const {
    glBindVertexArray(id());
}

} // namespace engine::gl
