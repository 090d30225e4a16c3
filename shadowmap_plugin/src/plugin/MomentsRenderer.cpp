#include "plugin/MomentsRenderer.h"

namespace shadowmap {

namespace shaders {
extern const char moments_glsl[];
extern const char moments_box_glsl[];
extern const char moments_vert[];
extern const char moments_from_depth_frag[];
extern const char moments_blur_frag[];
} // namespace shaders

namespace {

// The texture unit both programs read from (their samplers' binding 0).
constexpr unsigned kSourceUnit = 0;

engine::gl::Program compileMomentsProgram(const char* name, const char* fragment) {
    const std::string header = "#version 450 core\n";
    return engine::gl::Program::compile(
        name, {{GL_VERTEX_SHADER, header + shaders::moments_vert},
               {GL_FRAGMENT_SHADER, header + shaders::moments_glsl + shaders::moments_box_glsl + fragment}});
}

} // namespace

MomentsRenderer::MomentsRenderer()
    : fromDepth_(compileMomentsProgram("shadow moments from depth", shaders::moments_from_depth_frag)),
      blur_(compileMomentsProgram("shadow moments blur", shaders::moments_blur_frag)),
      texelSampler_(engine::gl::Sampler::create()),
      empty_(engine::gl::VertexArray::create()) {
    texelSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
    texelSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    texelSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void MomentsRenderer::fromDepth(unsigned mapLayers, int layer, const MomentsDepth& depth, float radius,
                                glm::ivec2 step) const {
    fromDepth_.use();
    fromDepth_.set("uLayer", layer);
    fromDepth_.set("uStep", step);
    fromDepth_.set("uRadius", radius);
    fromDepth_.set("uPerspective", depth.perspective ? 1 : 0);
    fromDepth_.set("uReversed", depth.reversed ? 1 : 0);
    fromDepth_.set("uNear", depth.nearPlane);
    fromDepth_.set("uFar", depth.farPlane);
    fromDepth_.set("uEvsm", depth.evsm ? 1 : 0);
    fromDepth_.set("uExponents", depth.exponents);
    glBindTextureUnit(kSourceUnit, mapLayers);
    texelSampler_.bind(kSourceUnit);
    empty_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(kSourceUnit, 0);
}

void MomentsRenderer::blur(unsigned rows, float radius, glm::ivec2 step) const {
    blur_.use();
    blur_.set("uStep", step);
    blur_.set("uRadius", radius);
    glBindTextureUnit(kSourceUnit, rows);
    texelSampler_.bind(kSourceUnit);
    empty_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(kSourceUnit, 0);
}

} // namespace shadowmap
