#pragma once
// Sampler: sampling state (filters, wrap, depth compare) kept apart from the texture, so one
// shadow map can be read both as depth values and with hardware comparison.
#include "engine/gl/Handle.h"

namespace engine::gl {

namespace detail {
struct SamplerTraits {
    static constexpr GLenum labelNamespace = GL_SAMPLER;
    static void destroy(GLuint name) noexcept { glDeleteSamplers(1, &name); }
};
} // namespace detail

class Sampler : public Handle<detail::SamplerTraits> {
public:
    Sampler() = default;

    static Sampler create();
    static Sampler wrap(GLuint name, Ownership ownership = Ownership::Adopt);

    void set(GLenum pname, GLint value);
    void setf(GLenum pname, GLfloat value);

    // glBindSampler: overrides the sampling state of texture unit `unit`.
    void bind(GLuint unit) const;

private:
    using Handle::Handle;
};

} // namespace engine::gl
