#pragma once
// How many GL objects our owners (Handle.h) hold right now, per kind. Every owner that will
// delete its name counts +1 from the moment it owns it and -1 when it deletes or release()s
// it (a borrowed name is not counted; a move hands the count over). A soak or a test reads
// the counts between frames to prove that nothing accumulates: a cache that never frees
// shows up as a count that keeps growing.
//
// Names deleted behind the owners' back (raw glDelete*) or made by raw glCreate* are not
// seen: every GL object the engine makes goes through an owner.
#include <epoxy/gl.h>

#include <cstdint>

namespace engine::gl {

struct LiveObjectCounts {
    std::int64_t textures = 0, framebuffers = 0, buffers = 0, programs = 0, shaders = 0,
                 samplers = 0, vertexArrays = 0, queries = 0;
    std::int64_t total() const {
        return textures + framebuffers + buffers + programs + shaders + samplers + vertexArrays + queries;
    }
};

// The counts now, over every context of the process.
LiveObjectCounts liveObjectCounts() noexcept;

namespace detail {
// Called by Handle: `delta` (+1 or -1) objects of the kind `labelNamespace` names
// (GL_TEXTURE, GL_FRAMEBUFFER, GL_BUFFER, GL_PROGRAM, GL_SHADER, GL_SAMPLER, GL_VERTEX_ARRAY,
// GL_QUERY).
void countOwnedObjects(GLenum labelNamespace, int delta) noexcept;
} // namespace detail

} // namespace engine::gl
