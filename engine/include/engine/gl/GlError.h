#pragma once
// Errors of the GL layer. GL reports most of its failures late and tersely (a glGetError
// flag, a framebuffer status, a shader log); these exceptions turn them into one readable
// message that names what we were doing.
#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace engine::gl {

class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A shader that failed to compile or a program that failed to link. The message names the
// program and the stage and quotes the offending source lines (see ShaderLog.h).
class ShaderError : public GlError {
public:
    using GlError::GlError;
};

// "GL_INVALID_ENUM", ...; the hex value for codes it does not know.
std::string glErrorName(GLenum error);

// "0x8CD6": how an enum we have no name for appears in a message.
std::string hexEnum(GLenum value);

// Throws GlError("GL error GL_INVALID_VALUE (and ...) at <where>") if any error flag is set.
// Drains every pending flag so the next check starts clean.
void checkGlError(const char* where);

} // namespace engine::gl
