#include "engine/gl/Sampler.h"

namespace engine::gl {

Sampler Sampler::create() {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    return Sampler(name, Ownership::Adopt, {});
}

Sampler Sampler::wrap(GLuint name, Ownership ownership) {
    return Sampler(name, ownership, {});
}

void Sampler::set(GLenum pname, GLint value) {
    glSamplerParameteri(id(), pname, value);
}

void Sampler::setf(GLenum pname, GLfloat value) {
    glSamplerParameterf(id(), pname, value);
}

void Sampler::bind(GLuint unit) const {
    glBindSampler(unit, id());
}

} // namespace engine::gl
