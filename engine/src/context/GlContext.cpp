#include "engine/context/GlContext.h"

#include <epoxy/gl.h>

namespace engine {

namespace {

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "";
}

} // namespace

GlContext::~GlContext() = default;

std::string GlContext::rendererString() const {
    return glString(GL_RENDERER);
}

std::string GlContext::versionString() const {
    return glString(GL_VERSION);
}

} // namespace engine
