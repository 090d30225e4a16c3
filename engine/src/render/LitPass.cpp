#include "engine/render/LitPass.h"

#include "engine/render/MaterialShading.h"
#include "engine/render/SceneGpu.h"
#include "engine/render/ShadingRegions.h"
#include "engine/scene/DrawOrder.h"
#include "engine/scene/FrustumCull.h"
#include "engine/scene/Scene.h"
#include "engine/util/Hasher.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

namespace shaders {
extern const char lit_vert[];
extern const char lit_frag[];
}

namespace {

// Without a plugin every light is fully visible and nothing is dimmed.
constexpr const char* kNoShadowsGlsl =
    "float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n"
    "    return 1.0;\n"
    "}\n"

    "vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {\n"
    "    return vec4(0.3, 0.3, 0.3, 1.0);\n"
    "}\n";

// A hook without a vertex part.
constexpr const char* kNoTexgenGlsl = "void lightTexgen(vec3 eyePosition) {}\n";

// std140 layout of lit.frag's LightData.
struct LightData {
    glm::vec4 positionRange;
    glm::vec4 direction;
    glm::vec4 radiance;
    glm::vec4 cone;
};

// What every pixel's shade depends on besides the hook's per-light inputs: the camera and
// target size, and every surface the lit pass may draw (which mesh, where, whether it
// receives shadows) with what decides its coverage (alpha mode, cutoff and base alpha,
// sidedness). The scene generation covers what only changes with a new scene (meshes,
// textures).
std::uint64_t shadeViewKey(const Frame& frame, std::uint64_t sceneGeneration) {
    Hasher hasher;
    hasher.add(sceneGeneration);
    hasher.add(frame.camera().eyeToWorld);
    hasher.add(frame.camera().projection);
    hasher.add(frame.camera().width);
    hasher.add(frame.camera().height);
    for (const MeshInstance& instance : frame.scene().meshInstances) {
        hasher.add(instance.mesh);
        hasher.add(instance.world);
        hasher.add(instance.revision);  // a deformed instance changes shape in place
        hasher.add(instance.receiveShadows);
    }
    for (const Material& material : frame.scene().materials) {
        hasher.add(material.alphaMode);
        hasher.add(material.alphaCutoff);
        hasher.add(material.baseColorFactor.a);
        hasher.add(material.doubleSided);
    }
    return hasher.value();
}

// lit.frag's LIGHT_DIRECTIONAL, LIGHT_SPOT and LIGHT_POINT.
int lightTypeCode(Light::Type type) {
    switch (type) {
    case Light::Type::Directional: return 0;
    case Light::Type::Spot: return 1;
    case Light::Type::Point: return 2;
    }
    return 2;
}

// The material variants (MaterialShading.h) the scene's primitives use (at least the plain
// one, for an empty scene).
std::vector<unsigned> variantsInUse(const Scene& scene, const SceneGpu& gpu) {
    std::vector<unsigned> variants;
    for (int mesh = 0; mesh < static_cast<int>(scene.meshes.size()); ++mesh)
        for (const SceneGpu::Primitive& primitive : gpu.meshPrimitives(mesh))
            if (const unsigned variant = materialFeatures(scene, gpu, primitive, MaterialUse::Shading);
                std::find(variants.begin(), variants.end(), variant) == variants.end())
                variants.push_back(variant);
    if (variants.empty()) variants.push_back(0);
    return variants;
}

// lit.frag's light defines: how many lights the pass shades, and FOR_EACH_LIGHT(F)
// expanding to F(slot, type code) for each of them, unrolled with literal arguments, or
// (RendererConfig::unrolledLightSum off) as one loop reading the types from a constant array.
std::string lightDefines(const Scene& scene, int lightCount, bool unrolled) {
    std::string defines = "#define LIGHT_COUNT " + std::to_string(lightCount) + "\n";
    if (lightCount == 0) return defines;
    std::string types;
    for (int slot = 0; slot < lightCount; ++slot) {
        const Light& light = scene.lights[scene.lightInstances[slot].light];
        const std::string type = std::to_string(lightTypeCode(light.type));
        types += (slot ? ", " : "") + type;
        if (unrolled) defines += (slot ? " F(" : "#define FOR_EACH_LIGHT(F) F(") + std::to_string(slot) + ", " + type + ")";
    }
    if (!unrolled)
        defines += "const int kLightTypes[LIGHT_COUNT] = int[](" + types + ");\n"
                   "#define FOR_EACH_LIGHT(F) for (int lightSlot = 0; lightSlot < LIGHT_COUNT; ++lightSlot) "
                   "{ F(lightSlot, kLightTypes[lightSlot]) }";
    defines += "\n";
    return defines;
}

// Splitting the lit pass by footprints draws a mesh once per region it touches. What that
// costs against what it spares, measured on llvmpipe (2-core EPYC, 1280x720): a shadow lookup
// takes about 4.5 ns of frame per covered pixel (showcase, camera orbiting: 5 ms per light
// over 67 % of the target), a triangle drawn once more about 78 ns (2CylinderEngine: the lit
// pass's binning, 9.4 ms of main-thread time for 121k triangles). So a split must spare
// lookups on more pixels than 17 per triangle it draws again.
constexpr double kPixelsPerRedrawnTriangle = 17.0;
// And it stays small: a light that would split the target into more regions stays out.
// Measured on content/scenes/lamps.gltf (four lamps, camera orbiting, 1280x720): at most 9
// regions limited two lamps (frame 23.0-24.6 -> 21.8-24.4 ms), 32 three (18.5-19.6 ms), 64
// all four in 33 regions and was no faster (20.2-22.7 against 19.3-23.4 ms).
constexpr std::size_t kMaxRegions = 32;

// Whether light `slot`'s shade is looked up in this frame's shaded image and not written
// to the shade cache: only then may a constant stand in for it outside its footprint (the
// cache holds exact shades only).
bool evaluatedUnstored(const ShadeCache::Plan& plan, int slot) {
    const ShadeCache::Source source = plan.sources[slot];
    if (source == ShadeCache::Source::Inline) return true;
    return source == ShadeCache::Source::Moving && (plan.writeArray == 0 || plan.channels[slot] < 0);
}

// The meshes the camera may see, for the footprints: their bounds (what a light can light),
// their footprints and triangles (what drawing one in one more region costs), and a rect
// holding every pixel they may cover.
struct VisibleMeshes {
    std::vector<Aabb> bounds;
    std::vector<PixelRect> footprints;
    std::vector<std::int64_t> triangles;
    PixelRect covered;
};

VisibleMeshes visibleMeshes(const Frame& frame, const glm::dmat4& viewProjection) {
    VisibleMeshes meshes;
    for (const MeshInstance& instance : frame.scene().meshInstances) {
        if (!boxIntersectsFrustum(viewProjection, instance.worldBounds)) continue;
        meshes.bounds.push_back(instance.worldBounds);
        meshes.footprints.push_back(
            projectedFootprint(viewProjection, instance.worldBounds, frame.camera().width, frame.camera().height));
        meshes.covered = enclosing(meshes.covered, meshes.footprints.back());
        std::int64_t triangles = 0;
        for (const SceneGpu::Primitive& primitive : frame.gpu().primitives(instance)) triangles += primitive.indexCount / 3;
        meshes.triangles.push_back(triangles);
    }
    return meshes;
}

// A light whose lookups a footprint could spare on `sparedPixels` of the covered rect.
struct LimitCandidate {
    int slot;
    PixelRect footprint;
    std::int64_t sparedPixels;
};

// The candidates that join the split, most pixels spared first, while it stays within
// kMaxRegions and spares more lookups than the meshes it draws more than once cost; `split`
// receives their regions (bit i of a region's set: the i-th light returned).
std::vector<LimitCandidate> lightsWorthLimiting(std::vector<LimitCandidate> candidates, const VisibleMeshes& meshes,
                                                int width, int height, std::vector<ShadingRegion>& split) {
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const LimitCandidate& a, const LimitCandidate& b) { return a.sparedPixels > b.sparedPixels; });
    std::vector<LimitCandidate> limited;
    std::int64_t spared = 0;
    for (const LimitCandidate& candidate : candidates) {
        std::vector<PixelRect> footprints;
        for (const LimitCandidate& light : limited) footprints.push_back(light.footprint);
        footprints.push_back(candidate.footprint);
        std::vector<ShadingRegion> trial = splitByFootprints(footprints, width, height);
        if (trial.size() > kMaxRegions) continue;
        std::int64_t redrawnTriangles = 0;
        for (std::size_t i = 0; i < meshes.footprints.size(); ++i) {
            const auto touched = std::count_if(trial.begin(), trial.end(), [&](const ShadingRegion& region) {
                return region.rect.intersects(meshes.footprints[i]);
            });
            redrawnTriangles += std::max<std::int64_t>(touched - 1, 0) * meshes.triangles[i];
        }
        if (double(spared + candidate.sparedPixels) <= double(redrawnTriangles) * kPixelsPerRedrawnTriangle) continue;
        spared += candidate.sparedPixels;
        limited.push_back(candidate);
        split = std::move(trial);
    }
    return limited;
}

} // namespace

LitPass::LitPass(const RendererConfig& config)
    : config_(config),
      lightBuffer_(gl::Buffer::create(sizeof(LightData) * kMaxLights, nullptr,
                                      GL_DYNAMIC_STORAGE_BIT)) {}

const gl::Program& LitPass::programFor(const LightVisibilityHook* hook, const std::string& lightDefinesGlsl,
                                      Output output, const std::string& loadShadesGlsl, unsigned variant) {
    // A hook without a version is known by its text (Frame.h).
    std::string hookIdentity;
    if (hook) hookIdentity = hook->glslVersion ? hook->owner : hook->owner + '\0' + hook->glsl + '\0' + hook->vertexGlsl;
    ProgramKey key{std::move(hookIdentity), hook ? hook->glslVersion : 0, lightDefinesGlsl, loadShadesGlsl, output,
                   variant};
    auto found = programs_.find(key);
    if (found != programs_.end()) return *found->second;
    const std::string visibilityGlsl = hook ? hook->glsl : kNoShadowsGlsl;
    const std::string vertexTail = hook && !hook->vertexGlsl.empty() ? hook->vertexGlsl : kNoTexgenGlsl;
    const std::string header = "#version 450 core\n#define MAX_LIGHTS " + std::to_string(kMaxLights) +
                               "\n#define LIGHTS_BLOCK_BINDING " + std::to_string(kLightsUniformBinding) + "\n" +
                               lightDefinesGlsl +
                               (output == Output::Comparison ? "#define LIGHT_DEBUG_VIEW\n" : "") +
                               (output == Output::ShadowMask ? "#define LIGHT_MASK_VIEW\n" : "") +
                               (config_.exposure != 1.0f ? "#define EXPOSURE\n" : "") +
                               (config_.toneMapping == RendererConfig::ToneMapping::PbrNeutral
                                    ? "#define TONE_MAPPING_PBR_NEUTRAL\n"
                                    : "") +
                               materialDefines(variant, MaterialUse::Shading);
    const std::string fragmentTail = visibilityGlsl + "\n" + loadShadesGlsl;
    auto program = std::make_unique<gl::Program>(gl::Program::compile(
        "lit", {{GL_VERTEX_SHADER, header + materialVertexGlsl() + shaders::lit_vert + "\n" + vertexTail},
                {GL_FRAGMENT_SHADER, header + materialFragmentGlsl() + materialSurfaceGlsl() + shaders::lit_frag + "\n" +
                                         fragmentTail}}));
    return *programs_.emplace(std::move(key), std::move(program)).first->second;
}

void LitPass::uploadLights(const Scene& scene, const FrameCamera& camera) {
    // Eye-space light data composed in double: V^-1 * L, then cast.
    const glm::dmat4 view = glm::inverse(camera.eyeToWorld);
    LightData lights[kMaxLights]{};
    lightCount_ = 0;
    for (const LightInstance& placed : scene.lightInstances) {
        if (lightCount_ == kMaxLights) break;
        const Light& light = scene.lights[placed.light];
        LightData& data = lights[lightCount_++];
        const glm::dvec3 eyePosition = glm::dvec3(view * glm::dvec4(placed.position(), 1.0));
        const glm::dvec3 eyeDirection = glm::normalize(glm::dmat3(view) * placed.direction());
        data.positionRange = glm::vec4(glm::vec3(eyePosition), static_cast<float>(light.range));
        data.direction = glm::vec4(glm::vec3(eyeDirection), 0.0f);
        data.radiance = glm::vec4(light.color * light.intensity, 0.0f);
        data.cone = glm::vec4(static_cast<float>(std::cos(light.outerConeAngle)),
                              static_cast<float>(std::cos(light.innerConeAngle)), 0.0f, 0.0f);
    }
    lightBuffer_.update(0, sizeof(lights), lights);
}

std::vector<std::pair<PixelRect, ShadeCache::Plan>> LitPass::footprintRegions(const Frame& frame) {
    const FrameCamera& camera = frame.camera();
    std::vector<std::pair<PixelRect, ShadeCache::Plan>> regions{
        {PixelRect::target(camera.width, camera.height), shadePlan_}};
    footprintLimitedLights_.clear();
    shadingRegionCount_ = 1;
    if (!config_.lightFootprints) return regions;
    const Scene& scene = frame.scene();
    const glm::dmat4 viewProjection = camera.projection * glm::inverse(camera.eyeToWorld);
    const VisibleMeshes meshes = visibleMeshes(frame, viewProjection);
    std::vector<LimitCandidate> candidates;
    for (int slot = 0; slot < static_cast<int>(shadePlan_.sources.size()); ++slot) {
        if (!evaluatedUnstored(shadePlan_, slot)) continue;
        const LightInstance& placed = scene.lightInstances[slot];
        const PixelRect footprint = lightFootprint(scene.lights[placed.light], placed, meshes.bounds, viewProjection,
                                                   camera.width, camera.height);
        const std::int64_t spared = meshes.covered.area() - intersection(meshes.covered, footprint).area();
        if (spared > 0) candidates.push_back({slot, footprint, spared});
    }
    std::vector<ShadingRegion> split;
    const std::vector<LimitCandidate> limited = lightsWorthLimiting(candidates, meshes, camera.width, camera.height, split);
    if (limited.empty()) return regions;
    regions.clear();
    for (const ShadingRegion& region : split) {
        ShadeCache::Plan plan = shadePlan_;
        for (std::size_t i = 0; i < limited.size(); ++i)
            if (!(region.footprints & (1u << i))) {
                plan.sources[limited[i].slot] = ShadeCache::Source::Constant;
                plan.constants[limited[i].slot] = 1.0f;
            }
        regions.emplace_back(region.rect, std::move(plan));
    }
    for (const LimitCandidate& light : limited) footprintLimitedLights_.push_back(light.slot);
    std::sort(footprintLimitedLights_.begin(), footprintLimitedLights_.end());
    shadingRegionCount_ = static_cast<int>(regions.size());
    return regions;
}

void LitPass::drawScene(const Frame& frame, const std::vector<Region>& regions, PassContext& context) {
    const Scene& scene = frame.scene();
    const glm::dmat4 view = glm::inverse(frame.camera().eyeToWorld);
    for (const Region& region : regions)
        for (const gl::Program* program : region.programs)
            if (program) {
                program->set("uProjection", glm::mat4(frame.camera().projection));
                program->set("uAmbient", config_.ambient);
                program->set("uExposure", config_.exposure);
            }
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsUniformBinding, lightBuffer_.id());
    const gl::Program* current = nullptr;

    const glm::dmat4 viewProjection = frame.camera().projection * view;
    // Camera culling (a mesh whose bounds miss the view frustum costs no draw), nearest
    // first so the depth test spares hidden fragments their shading.
    const DrawOrder order = nearestFirst(scene, viewProjection, frame.camera().position());
    culledInstances_ = order.culled;
    const PixelRect target = PixelRect::target(frame.camera().width, frame.camera().height);
    const bool split = regions.size() > 1;
    // Each region draws, in the same nearest-first order, the meshes whose footprint touches
    // it; a pixel lies in one region, so it sees the same fragments in the same order as
    // without the split.
    std::vector<PixelRect> meshFootprints;
    if (split) {
        glEnable(GL_SCISSOR_TEST);
        for (const int index : order.instances)
            meshFootprints.push_back(projectedFootprint(viewProjection, scene.meshInstances[index].worldBounds,
                                                        target.x1, target.y1));
    }
    for (const Region& region : regions) {
        if (split) glScissor(region.rect.x0, region.rect.y0, region.rect.x1 - region.rect.x0, region.rect.y1 - region.rect.y0);
        for (std::size_t drawn = 0; drawn < order.instances.size(); ++drawn) {
            if (split && !meshFootprints[drawn].intersects(region.rect)) continue;
            drawInstance(frame, order.instances[drawn], view, region.programs, current, context);
        }
    }
    if (split) glDisable(GL_SCISSOR_TEST);
}

void LitPass::drawInstance(const Frame& frame, int index, const glm::dmat4& view, const Variants& programs,
                           const gl::Program*& current, PassContext& context) {
    const Scene& scene = frame.scene();
    const MeshInstance& instance = scene.meshInstances[index];
    // Compose in double so only the camera-relative result is rounded to float.
    const glm::dmat4 modelView = view * frame.gpu().modelMatrix(instance);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(modelView)));
    // A mirroring transform turns counter-clockwise triangles clockwise on screen.
    glFrontFace(glm::determinant(glm::dmat3(instance.world)) < 0.0 ? GL_CW : GL_CCW);
    for (const SceneGpu::Primitive& primitive : frame.gpu().primitives(instance)) {
        const Material& material = materialOf(scene, primitive);
        const unsigned variant = materialFeatures(scene, frame.gpu(), primitive, MaterialUse::Shading);
        const gl::Program& program = *programs[variant];
        if (&program != current) {
            program.use();
            current = &program;
        }
        program.set("uModelView", glm::mat4(modelView));
        program.set("uNormalMatrix", glm::mat3(normalMatrix));
        program.set("uReceiveShadows", instance.receiveShadows && primitive.receiveShadows ? 1 : 0);
        applyMaterial(program, scene, frame.gpu(), primitive, variant, MaterialUse::Shading);
        if (material.doubleSided) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE);
        context.countDraw(frame.gpu().draw(primitive));
    }
}

void LitPass::addPass(Frame& frame, const std::string& name, ResourceHandle target, Output output,
                      int maskSlot) {
    const auto& hook = frame.lightVisibility();
    const int lightCount =
        std::min(static_cast<int>(frame.scene().lightInstances.size()), kMaxLights);
    // Only the shaded image uses the shade cache: the per-light views always ask the hook.
    if (output == Output::Color) {
        const bool cacheable = config_.shadeCache && hook;
        shadePlan_ = cacheable ? shadeCache_.plan(shadeViewKey(frame, sceneGeneration_), *hook, lightCount,
                                                  frame.camera().width, frame.camera().height)
                               : ShadeCache::uncached(lightCount);
    }
    const bool color = output == Output::Color;
    // The shaded image may be split by light footprints, each region with a shade plan of its
    // own; the per-light views always ask the hook, everywhere.
    const std::vector<std::pair<PixelRect, ShadeCache::Plan>> plans =
        color ? footprintRegions(frame)
              : std::vector<std::pair<PixelRect, ShadeCache::Plan>>{
                    {PixelRect::target(frame.camera().width, frame.camera().height), ShadeCache::uncached(lightCount)}};
    const std::string lights = lightDefines(frame.scene(), lightCount, config_.unrolledLightSum);
    const std::vector<unsigned> variants = variantsInUse(frame.scene(), frame.gpu());
    std::vector<Region> regions;
    bool evaluatesHook = false;
    for (const auto& [rect, plan] : plans) {
        Region& region = regions.emplace_back();
        region.rect = rect;
        // A shaded image that takes every light's shade from the cache needs none of the hook's
        // code: leaving it out spares llvmpipe its interpolated inputs and uniforms (measured:
        // 16.8 -> 15.7 ms for the showcase at 1280x720, whose unshadowed frame takes 14.0).
        region.evaluatesHook = hook && (!color || plan.evaluatesHook());
        evaluatesHook = evaluatesHook || region.evaluatesHook;
        const std::string loadShadesGlsl = plan.glsl();
        for (const unsigned variant : variants)
            region.programs[variant] =
                &programFor(region.evaluatesHook ? &*hook : nullptr, lights, output, loadShadesGlsl, variant);
    }
    const LightVisibilityHook* shading = evaluatesHook ? &*hook : nullptr;
    std::vector<float> dimming(kMaxLights, 0.0f);
    if (hook)
        std::copy_n(hook->dimming.begin(), std::min<std::size_t>(hook->dimming.size(), kMaxLights), dimming.begin());
    // Setup runs inside addPass, after both callbacks were built: share the handles it
    // declares with the execute callback through one small heap object.
    struct Handles { ResourceHandle target, depth; };
    auto handles = std::make_shared<Handles>();
    handles->target = target;
    const ShadeCache::Plan* shadePlan = color && shadePlan_.layers > 0 ? &shadePlan_ : nullptr;
    frame.graph().addPass(
        name,
        [&](PassBuilder& builder) {
            if (shading)
                for (ResourceHandle read : shading->reads) builder.read(read);
            handles->depth = builder.create(
                name + "_depth",
                {frame.camera().width, frame.camera().height, TextureFormat::Depth32F});
            handles->target = builder.write(target);
            PassTargets targets;
            const glm::vec4 clear = color ? glm::vec4(config_.clearColor, 1.0f) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
            targets.colors.push_back({handles->target, -1, std::array<float, 4>{clear.r, clear.g, clear.b, clear.a}});
            targets.depth = DepthTarget{handles->depth, -1, 1.0f};
            // The shade cache's arrays live across frames (ShadeCache.h): imported, read and
            // written here; the written one's layers are the extra colour outputs.
            if (shadePlan) {
                const TextureDesc desc{frame.camera().width, frame.camera().height, TextureFormat::RGBA32F,
                                       shadePlan->layers};
                if (shadePlan->readArray)
                    builder.read(frame.graph().importTexture("shade_cache_read", desc, shadePlan->readArray));
                if (shadePlan->writeArray) {
                    const ResourceHandle written = builder.write(
                        frame.graph().importTexture("shade_cache_written", desc, shadePlan->writeArray));
                    for (int layer = 0; layer < shadePlan->layers; ++layer)
                        targets.colors.push_back({written, layer, std::nullopt});
                }
            }
            builder.setTargets(targets);
            PassState state;  // depth test, back faces culled, viewport: the target's size
            state.srgbWrites = color;
            builder.setState(state);
        },
        [this, &frame, regions, output, maskSlot, shading, shadePlan, dimming](PassContext& context) {
            if (output == Output::Color) uploadLights(frame.scene(), frame.camera());
            if (shadePlan && shadePlan->readArray) glBindTextureUnit(ShadeCache::kTextureUnit, shadePlan->readArray);
            for (const Region& region : regions)
                for (const gl::Program* program : region.programs) {
                    if (!program) continue;
                    program->set("uMaskLight", maskSlot);
                    program->set("uLightDimming", dimming);
                    if (region.evaluatesHook && shading->bind) shading->bind(*program, context);
                }
            drawScene(frame, regions, context);
            if (shadePlan) {
                glBindTextureUnit(ShadeCache::kTextureUnit, 0);
                shadeCache_.commit(*shadePlan);
            }
        });
}

void LitPass::sceneChanged() {
    ++sceneGeneration_;
    shadeCache_.clear();
}

void LitPass::addTo(Frame& frame, ResourceHandle colorTarget) {
    addPass(frame, "lit", colorTarget, Output::Color, -1);
}

void LitPass::addLightViewTo(Frame& frame, int slot, LightView view, ResourceHandle target) {
    const bool mask = view == LightView::ShadowMask;
    addPass(frame, (mask ? "shadow_mask_" : "shadow_compare_") + std::to_string(slot), target,
            mask ? Output::ShadowMask : Output::Comparison, slot);
}

} // namespace engine
