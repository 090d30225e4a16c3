#include "engine/gl/Query.h"

namespace engine::gl {

Query Query::create(GLenum target) {
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    return Query(name, Ownership::Adopt, {target});
}

void Query::begin() const {
    glBeginQuery(target(), id());
}

void Query::end() const {
    glEndQuery(target());
}

std::optional<std::uint64_t> Query::resultIfReady() const {
    if (!id()) return std::nullopt;
    GLint ready = GL_FALSE;
    glGetQueryObjectiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) return std::nullopt;
    GLuint64 result = 0;
    glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &result);
    return result;
}

} // namespace engine::gl
