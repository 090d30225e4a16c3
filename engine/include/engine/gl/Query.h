#pragma once
// Query: a GL query object (glCreateQueries), e.g. GL_SAMPLES_PASSED to count the samples a
// set of draws left after the depth and stencil tests. Results arrive after the GPU has run
// the draws: resultIfReady() never waits, so a report read each frame costs no stall.
#include "engine/gl/Handle.h"

#include <cstdint>
#include <optional>

namespace engine::gl {

namespace detail {
struct QueryTraits {
    static constexpr GLenum labelNamespace = GL_QUERY;
    static void destroy(GLuint name) noexcept { glDeleteQueries(1, &name); }
};
struct QueryInfo {
    GLenum target = 0;
};
} // namespace detail

class Query : public Handle<detail::QueryTraits, detail::QueryInfo> {
public:
    Query() = default;

    static Query create(GLenum target);

    GLenum target() const noexcept { return info().target; }

    // Brackets the draws the query counts; one query of a target may be active at a time.
    void begin() const;
    void end() const;

    // The last ended query's result when the GPU has it, without waiting; nullopt before.
    std::optional<std::uint64_t> resultIfReady() const;

private:
    using Handle::Handle;
};

} // namespace engine::gl
