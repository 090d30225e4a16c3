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

// `defines`: #define lines for the fragment stage.
engine::gl::Program compileMomentsProgram(const std::string& name, const char* fragment,
                                          const std::string& defines = "") {
    const std::string header = "#version 450 core\n";
    return engine::gl::Program::compile(
        name, {{GL_VERTEX_SHADER, header + shaders::moments_vert},
               {GL_FRAGMENT_SHADER, header + defines + shaders::moments_glsl + shaders::moments_box_glsl + fragment}});
}

// The kinds of layer the first pass is built for: one bit each.
unsigned kindOf(const MomentsDepth& depth) {
    return (depth.evsm ? 1u : 0u) | (depth.perspective ? 2u : 0u) | (depth.reversed ? 4u : 0u);
}

} // namespace

const engine::gl::Program& MomentsRenderer::fromDepthProgram(const MomentsDepth& depth) const {
    const unsigned kind = kindOf(depth);
    if (auto found = fromDepth_.find(kind); found != fromDepth_.end()) return found->second;
    const std::string defines = "#define MOMENTS_EVSM " + std::to_string(depth.evsm ? 1 : 0) +
                                "\n#define MOMENTS_PERSPECTIVE " + std::to_string(depth.perspective ? 1 : 0) +
                                "\n#define MOMENTS_REVERSED " + std::to_string(depth.reversed ? 1 : 0) + "\n";
    return fromDepth_
        .emplace(kind, compileMomentsProgram("shadow moments from depth " + std::to_string(kind),
                                             shaders::moments_from_depth_frag, defines))
        .first->second;
}

MomentsRenderer::MomentsRenderer()
    : blur_(compileMomentsProgram("shadow moments blur", shaders::moments_blur_frag)),
      texelSampler_(engine::gl::Sampler::create()),
      empty_(engine::gl::VertexArray::create()) {
    texelSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
    texelSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    texelSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void MomentsRenderer::fromDepth(unsigned mapLayers, int layer, const MomentsDepth& depth, float radius,
                                glm::ivec2 step) const {
    const engine::gl::Program& program = fromDepthProgram(depth);
    program.use();
    program.set("uLayer", layer);
    program.set("uStep", step);
    program.set("uRadius", radius);
    program.set("uNear", depth.nearPlane);
    program.set("uFar", depth.farPlane);
    program.set("uExponents", depth.exponents);
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
