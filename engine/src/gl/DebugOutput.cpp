#include "engine/gl/DebugOutput.h"

#include <epoxy/gl.h>

#include <cstdio>

namespace engine::gl {

namespace {

const char* sourceName(GLenum source) {
    switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
    }
}

const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
    }
}

void GLAPIENTRY printMessage(GLenum source, GLenum type, GLuint id, GLenum /*severity*/,
                             GLsizei length, const GLchar* message, const void* /*user*/) {
    std::fprintf(stderr, "GL debug (%s, %s, id %u): %.*s\n", sourceName(source), typeName(type),
                 id, static_cast<int>(length), message);
}

} // namespace

void installDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    // Synchronous: the message is printed inside the offending call, so a breakpoint on
    // printMessage shows the caller's stack.
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(printMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_HIGH, 0, nullptr, GL_TRUE);
}

} // namespace engine::gl
