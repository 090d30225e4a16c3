#include "plugin/DepthRenderer.h"

#include "math/FrustumCull.h"

#include "engine/gl/Framebuffer.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"

namespace shadowmap {

namespace shaders {
extern const char depth_vert[];
extern const char depth_frag[];
}

DepthRenderer::DepthRenderer()
    : program_(engine::gl::Program::compile(
          "shadow depth", {{GL_VERTEX_SHADER, std::string("#version 450 core\n") + shaders::depth_vert},
                           {GL_FRAGMENT_SHADER, std::string("#version 450 core\n") + shaders::depth_frag}})) {}

DepthDrawCounts DepthRenderer::render(const engine::Frame& frame, engine::PassContext& context,
                                      unsigned map, int layer, int resolution,
                                      const glm::dmat4& viewProjection,
                                      const ShadowSettings& settings, bool drawCasters) {
    engine::gl::Framebuffer framebuffer = engine::gl::Framebuffer::create();
    if (layer < 0) glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, map, 0);
    else glNamedFramebufferTextureLayer(framebuffer.id(), GL_DEPTH_ATTACHMENT, map, 0, layer);
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
    // Both faces: open casters must cast too; the offset keeps lit front faces from acne.
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    const glm::vec2 offset = settings.effectivePolygonOffset();
    glPolygonOffset(offset.x, offset.y);
    program_.use();

    const engine::Scene& scene = frame.scene();
    for (const engine::MeshInstance& instance : scene.meshInstances) {
        if (!instance.castShadows) continue;
        if (!boxIntersectsFrustum(viewProjection, instance.worldBounds)) {
            ++counts.castersCulled;
            continue;
        }
        // P_light * L^-1 * M in double: only the light-relative product is rounded.
        program_.set("uLightModelViewProjection", glm::mat4(viewProjection * instance.world));
        for (const auto& primitive : frame.gpu().primitives(instance.mesh)) {
            const std::uint64_t triangles = frame.gpu().draw(primitive);
            context.countDraw(triangles);
            ++counts.draws;
            counts.triangles += triangles;
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_CULL_FACE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return counts;
}

} // namespace shadowmap
