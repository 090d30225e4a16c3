#pragma once
// The shadow plugin's shipped GLSL (shadowmap_plugin/shaders), embedded into the test binary
// from the same files the plugin embeds (cmake/EmbedText.cmake), so GL tests run the code
// that ships rather than a copy written for the test.
#include "engine/render/Frame.h"

#include <string>

namespace shadowmap::shaders {
extern const char texgen_glsl[];
extern const char visibility_glsl[];
} // namespace shadowmap::shaders

namespace shadowmap::test {

// What the lit pass puts before the plugin's hook (LitPass.cpp): the version and MAX_LIGHTS,
// which sizes the hook's uniform arrays.
inline std::string hookPrelude() {
    return "#version 450 core\n#define MAX_LIGHTS " + std::to_string(engine::kMaxLights) + "\n";
}

} // namespace shadowmap::test
