#include "plugin/DepthRenderer.h"

#include "engine/scene/FrustumCull.h"

#include "engine/gl/Framebuffer.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"

namespace shadowmap {

namespace shaders {
extern const char depth_vert[];
extern const char depth_frag[];
}

namespace {

// One source per stage; variants by #define (as bgfx's shadow examples do).
engine::gl::Program compileDepthProgram(const std::string& name, const std::string& defines) {
    const std::string header = "#version 450 core\n" + defines;
    return engine::gl::Program::compile(name, {{GL_VERTEX_SHADER, header + shaders::depth_vert},
                                               {GL_FRAGMENT_SHADER, header + shaders::depth_frag}});
}

void setPolygonOffset(const glm::vec2& offset) {
    if (offset == glm::vec2(0.0f)) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        return;
    }
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(offset.x, offset.y);
}

} // namespace

DepthRenderer::DepthRenderer()
    : plain_(compileDepthProgram("shadow depth", "")),
      peel2D_(compileDepthProgram("shadow depth peel", "#define PEEL\n")),
      peelArray_(compileDepthProgram("shadow depth peel (cube)", "#define PEEL\n#define PEEL_ARRAY\n")) {}

DepthDrawCounts DepthRenderer::render(const engine::Frame& frame, engine::PassContext& context,
                                      unsigned target, int layer, int resolution,
                                      const glm::dmat4& viewProjection, const DepthPassStyle& style,
                                      bool drawCasters) {
    engine::gl::Framebuffer framebuffer = engine::gl::Framebuffer::create();
    if (layer < 0) glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, target, 0);
    else glNamedFramebufferTextureLayer(framebuffer.id(), GL_DEPTH_ATTACHMENT, target, 0, layer);
    glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);  // depth only: no color writes
    glNamedFramebufferReadBuffer(framebuffer.id(), GL_NONE);
    framebuffer.requireComplete("shadow map framebuffer");

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, resolution, resolution);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &farDepth);
    DepthDrawCounts counts;
    if (!drawCasters) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return counts;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glCullFace(GL_FRONT);  // used only for closed casters under backFacesOnly

    const engine::gl::Program& program =
        !style.firstLayer ? plain_ : style.firstLayerIsArray ? peelArray_ : peel2D_;
    program.use();
    if (style.firstLayer) {
        glBindTextureUnit(0, style.firstLayer);
        if (style.firstLayerIsArray) program.set("uFirstLayerIndex", std::max(layer, 0));
        program.set("uPeelEpsilon", style.peelEpsilon);
    }

    const engine::Scene& scene = frame.scene();
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows) continue;
        if (!engine::boxIntersectsFrustum(viewProjection, instance.worldBounds)) {
            ++counts.castersCulled;
            continue;
        }
        const bool backOnly = style.backFacesOnly && style.closedMeshes &&
                              (*style.closedMeshes)[instance.mesh];
        if (backOnly) glEnable(GL_CULL_FACE);
        else glDisable(GL_CULL_FACE);
        setPolygonOffset(style.backFacesOnly && !backOnly ? style.openCasterOffset : style.polygonOffset);
        // A mirroring transform turns counter-clockwise triangles clockwise.
        glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
        // P_light * L^-1 * M in double: only the light-relative product is rounded.
        program.set("uLightModelViewProjection", glm::mat4(viewProjection * instance.world));
        for (const auto& primitive : frame.gpu().primitives(instance.mesh)) {
            const std::uint64_t triangles = frame.gpu().draw(primitive);
            context.countDraw(triangles);
            ++counts.draws;
            counts.triangles += triangles;
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glEnable(GL_CULL_FACE);
    if (style.firstLayer) glBindTextureUnit(0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return counts;
}

} // namespace shadowmap
