#include "engine/gl/GlError.h"

#include <cstdio>

namespace engine::gl {

std::string glErrorName(GLenum error) {
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
    default: return hexEnum(error);
    }
}

std::string hexEnum(GLenum value) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", value);
    return hex;
}

void checkGlError(const char* where) {
    // Several flags can be pending at once; each glGetError call returns and clears one.
    // The bound keeps a lost context (which may report forever) from hanging us.
    constexpr int kMaxFlags = 8;
    std::string names;
    for (int i = 0; i < kMaxFlags; ++i) {
        const GLenum error = glGetError();
        if (error == GL_NO_ERROR) break;
        names += (names.empty() ? "" : ", ") + glErrorName(error);
    }
    if (!names.empty()) throw GlError("GL error " + names + " at " + where);
}

} // namespace engine::gl
