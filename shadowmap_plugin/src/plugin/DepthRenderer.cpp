#include "plugin/DepthRenderer.h"

#include "plugin/CasterLods.h"
#include "technique/CasterLodChoice.h"
#include "technique/Techniques.h"

#include "engine/scene/FrustumCull.h"

#include "engine/render/MaterialShading.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/Scene.h"

namespace shadowmap {

namespace shaders {
extern const char depth_vert[];
extern const char depth_frag[];
}

namespace {

// The texture unit of a depth program's input (Woo pass 2's first layer): beside the
// material's base color texture.
constexpr unsigned kDepthInputUnit = engine::kMaterialTextureUnit + 1;

// The shared sources with the program's own part after each (DepthProgram.h).
engine::gl::Program compileDepthProgram(const DepthProgram& program, unsigned materialFeatures) {
    const std::string header = "#version 450 core\n#define DEPTH_INPUT_UNIT " + std::to_string(kDepthInputUnit) +
                               "\n" + engine::materialDefines(materialFeatures, engine::MaterialUse::ShadowCasting);
    return engine::gl::Program::compile(
        program.name,
        {{GL_VERTEX_SHADER, header + engine::materialVertexGlsl() + shaders::depth_vert + program.vertexGlsl},
         {GL_FRAGMENT_SHADER, header + engine::materialFragmentGlsl() + shaders::depth_frag + program.fragmentGlsl}});
}

// The offset of one caster's draws when it differs from the pass's (backface's open casters).
void setPolygonOffset(const glm::vec2& offset, const DepthPassStyle& style) {
    if (offset == glm::vec2(0.0f)) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        return;
    }
    glEnable(GL_POLYGON_OFFSET_FILL);
    const glm::vec3 value = signedOffset(offset, style);
    glPolygonOffsetClamp(value.x, value.y, value.z);  // a clamp of 0 clamps nothing
}

} // namespace

DepthRenderer::DepthRenderer() : empty_(engine::gl::VertexArray::create()) {
    // The opaque casters' programs, which every scene with shadows uses, before the first frame.
    for (const DepthProgram* depthProgram : depthPrograms()) program(*depthProgram, 0);
}

const engine::gl::Program& DepthRenderer::program(const DepthProgram& depthProgram, unsigned materialFeatures) {
    const auto key = std::make_pair(&depthProgram, materialFeatures);
    if (auto found = programs_.find(key); found != programs_.end()) return found->second;
    return programs_.emplace(key, compileDepthProgram(depthProgram, materialFeatures)).first->second;
}

DepthDrawCounts DepthRenderer::draw(const engine::Frame& frame, engine::PassContext& context,
                                    const glm::dmat4& viewProjection, const DepthPassStyle& style) {
    DepthDrawCounts counts;
    const DepthProgram& depthProgram = *style.program;
    if (style.inputTexture != 0) glBindTextureUnit(kDepthInputUnit, style.inputTexture);
    const engine::gl::Program* current = nullptr;
    // Switches to the program a caster's material needs, with the pass's own uniforms.
    auto use = [&](unsigned materialFeatures) -> const engine::gl::Program& {
        const engine::gl::Program& next = program(depthProgram, materialFeatures);
        if (&next == current) return next;
        current = &next;
        next.use();
        next.set("uReversedZ", style.reversedZ ? 1 : 0);
        next.set("uFullScreenLayer", 0);
        for (const DepthUniform& uniform : style.uniforms) next.set(uniform.name, uniform.value);
        return next;
    };
    use(0);

    const engine::Scene& scene = frame.scene();
    const engine::SceneGpu& gpu = frame.gpu();
    // Casters, and for a style that asks, receivers that cast nothing (DepthPassStyle.h).
    const auto drawn = [&style](bool casts, bool receives) {
        return casts || (style.drawsNonCastingReceivers && receives);
    };
    for (std::size_t index = 0; index < scene.meshInstances.size(); ++index) {
        const engine::MeshInstance& instance = scene.meshInstances[index];
        if (!drawn(instance.castShadows, instance.receiveShadows)) continue;
        if (!engine::boxIntersectsFrustum(viewProjection, instance.worldBounds)) {
            ++counts.castersCulled;
            context.countCulledDraw();
            continue;
        }
        if (style.unseenCasters && index < style.unseenCasters->size() && (*style.unseenCasters)[index]) {
            ++counts.castersUnseen;
            context.countCulledDraw();
            continue;
        }
        if (style.backFacesOnly) {
            const bool closed = style.closedMeshes && (*style.closedMeshes)[instance.mesh];
            if (closed) glEnable(GL_CULL_FACE);  // the pass culls front faces
            else glDisable(GL_CULL_FACE);
            setPolygonOffset(closed ? style.polygonOffset : style.openCasterOffset, style);
        }
        // caster_lod: the coarsest level within the allowed fraction of a texel here.
        int level = 0;
        if (style.casterLods && style.lodTexelFraction > 0.0) {
            const std::vector<double>& errors = style.casterLods->errors(instance.mesh);
            if (!errors.empty())
                level = coarsestLevelWithin(
                    errors, largestScale(instance.world),
                    style.lodTexelFraction * texelSizeAt(viewProjection, instance.worldBounds, style.mapResolution));
        }
        // A mirroring transform turns counter-clockwise triangles clockwise.
        glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
        // P_light * L^-1 * M in double: only the light-relative product is rounded.
        const glm::mat4 lightModelViewProjection(viewProjection * gpu.modelMatrix(instance));
        const std::vector<engine::SceneGpu::Primitive>& primitives = gpu.primitives(instance);
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const engine::SceneGpu::Primitive& primitive = primitives[p];
            // KHR_lights_shadows on the primitive: a caster only if instance and primitive cast.
            if (!drawn(instance.castShadows && primitive.castShadows,
                       instance.receiveShadows && primitive.receiveShadows))
                continue;
            const unsigned features =
                engine::materialFeatures(scene, gpu, primitive, engine::MaterialUse::ShadowCasting);
            if (style.cullsSingleSidedBackFaces) {
                const bool doubleSided = primitive.material >= 0 && scene.materials[primitive.material].doubleSided;
                if (doubleSided) glDisable(GL_CULL_FACE);
                else glEnable(GL_CULL_FACE);
            }
            const engine::gl::Program& drawing = use(features);
            drawing.set("uLightModelViewProjection", lightModelViewProjection);
            engine::applyMaterial(drawing, scene, gpu, primitive, features, engine::MaterialUse::ShadowCasting);
            const std::uint64_t triangles = style.casterLods
                                                ? style.casterLods->draw(gpu, primitive, instance.mesh, p, level)
                                                : gpu.draw(primitive);
            context.countDraw(triangles);
            ++counts.draws;
            if (counts.levelDraws.size() <= static_cast<std::size_t>(level)) counts.levelDraws.resize(level + 1);
            ++counts.levelDraws[level];
            counts.triangles += triangles;
        }
    }
    if (depthProgram.drawsFullScreenLayer) {
        // Woo pass 2, last: the far plane as one more layer (not clipped), so a texel whose
        // ray meets one surface and then nothing holds the midpoint between that surface and
        // far instead of far itself. Without it, a light inside a closed box lit what lies
        // just outside the box's silhouettes (2x2 PCF reads the neighbouring "nothing
        // behind" texels: 0.06% of the pixels that must be dark, tools/shadowmap-stress
        // special/light_inside_box). Texels with no surface at all fail the peel test and
        // stay far. Woo is never backface, so nothing is culled. The layer is the pass's
        // last draw, without the offset and depth-clamped.
        glDisable(GL_POLYGON_OFFSET_FILL);
        glEnable(GL_DEPTH_CLAMP);
        use(0).set("uFullScreenLayer", 1);
        empty_.bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }
    if (style.inputTexture != 0) glBindTextureUnit(kDepthInputUnit, 0);
    return counts;
}

} // namespace shadowmap
