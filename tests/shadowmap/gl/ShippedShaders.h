#pragma once
// The shadow plugin's shipped GLSL (shadowmap_plugin/shaders), embedded into the test binary
// from the same files the plugin embeds (cmake/EmbedText.cmake), so GL tests run the code
// that ships rather than a copy written for the test.
#include "plugin/ShadowBlock.h"

#include "engine/gl/Buffer.h"
#include "engine/render/Frame.h"

#include <string>

namespace shadowmap::shaders {
extern const char shadow_data_glsl[];
extern const char texgen_glsl[];
extern const char map_shapes_glsl[];
extern const char visibility_glsl[];
extern const char moments_glsl[];  // embedded with shadowmap_technique
} // namespace shadowmap::shaders

namespace shadowmap::test {

// What comes before the plugin's shipped functions in a lit shader: the version and
// MAX_LIGHTS (LitPass.cpp), which sizes the arrays of the plugin's block, the block with
// the constants it is defined from, and the moments' depth functions map_shapes.glsl calls
// (HookGlsl.cpp puts them first, in this order).
inline std::string hookPrelude() {
    return "#version 450 core\n#define MAX_LIGHTS " + std::to_string(engine::kMaxLights) + "\n" +
           shadowBlockGlslDefines() + shaders::shadow_data_glsl + shaders::moments_glsl;
}

// The block filled as the plugin fills it, bound where the shipped code reads it. Keep the
// returned buffer alive while drawing.
inline engine::gl::Buffer bindShadowBlock(const ShadowBlock& block) {
    engine::gl::Buffer buffer = engine::gl::Buffer::create(sizeof(ShadowBlock), &block);
    buffer.bindBase(GL_UNIFORM_BUFFER, kShadowBlockBinding);
    return buffer;
}

} // namespace shadowmap::test
