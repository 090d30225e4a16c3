#include "technique/DepthFormatGl.h"

#include <epoxy/gl.h>

#include <cmath>

namespace shadowmap {

unsigned glInternalFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return GL_DEPTH_COMPONENT16;
    case DepthFormat::D24: return GL_DEPTH_COMPONENT24;
    case DepthFormat::D32F: return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT24;
}

double depthStep(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return 1.0 / 65535.0;
    case DepthFormat::D24: return 1.0 / 16777215.0;
    case DepthFormat::D32F: return std::ldexp(1.0, -24);
    }
    return 1.0 / 16777215.0;
}

engine::TextureFormat graphFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::D16: return engine::TextureFormat::Depth16;
    case DepthFormat::D24: return engine::TextureFormat::Depth24;
    case DepthFormat::D32F: return engine::TextureFormat::Depth32F;
    }
    return engine::TextureFormat::Depth24;
}

} // namespace shadowmap
