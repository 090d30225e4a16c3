#pragma once
// VertexArray: where vertex attributes come from (glCreateVertexArrays, DSA setup).
// Core profile draws nothing without one bound, even when the vertex shader reads no
// attributes (a full-screen triangle from gl_VertexID): bind an empty one then.
#include "engine/gl/Handle.h"

namespace engine::gl {

class Buffer;

namespace detail {
struct VertexArrayTraits {
    static constexpr GLenum labelNamespace = GL_VERTEX_ARRAY;
    static void destroy(GLuint name) noexcept { glDeleteVertexArrays(1, &name); }
};
} // namespace detail

class VertexArray : public Handle<detail::VertexArrayTraits> {
public:
    VertexArray() = default;

    static VertexArray create();
    static VertexArray wrap(GLuint name, Ownership ownership = Ownership::Adopt);

    // Feeds float attribute `index` from `buffer`, `components` values of `type` per vertex,
    // starting `offset` bytes in. stride 0 means tightly packed, as in glVertexAttribPointer.
    // normalized: integer data read as [0,1] / [−1,1] (e.g. glTF normalized texcoords).
    // Each attribute gets its own buffer binding point (= index), so layouts may differ.
    void attribute(GLuint index, const Buffer& buffer, GLint components, GLenum type,
                   GLsizei stride, GLuint offset = 0, bool normalized = false);

    // Indices for glDrawElements.
    void elementBuffer(const Buffer& buffer);

    void bind() const;

private:
    using Handle::Handle;
};

} // namespace engine::gl
