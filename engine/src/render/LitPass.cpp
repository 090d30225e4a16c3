#include "engine/render/LitPass.h"

#include "engine/render/FootprintSplit.h"
#include "engine/render/LitLights.h"
#include "engine/render/MaterialShading.h"
#include "engine/render/SceneGpu.h"
#include "engine/scene/DrawOrder.h"
#include "engine/scene/FrustumCull.h"
#include "engine/scene/Scene.h"
#include "engine/util/Hasher.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace engine {

namespace {

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

// Warm-up for motion compiles a region's programs for every subset of the lights a split may
// limit, up to this many lights (2^4 = 16 plans per material variant); with more, only the
// regions of the warm-up's view. Measured on llvmpipe at 1280x720, a one-frame engine-render
// run, still / --orbit-camera / --orbit-light: lamps (four spots) 0.74 / 4.24 / 1.47 s,
// showcase 0.74 / 1.48 / 0.99 s; in return no frame of a 90-frame orbit compiles (the lamps'
// camera orbit: max frame 1448 -> 46 ms).
constexpr std::size_t kMaxWarmedUpSplitLights = 4;

// Each light's dimming as the hook gives it (0 without a hook), for uLightDimming.
std::vector<float> lightDimming(const Frame& frame) {
    std::vector<float> dimming(kMaxLights, 0.0f);
    if (const auto& hook = frame.lightVisibility())
        std::copy_n(hook->dimming.begin(), std::min<std::size_t>(hook->dimming.size(), kMaxLights), dimming.begin());
    return dimming;
}

// The plans a motion leads the shade cache to (ShadeCache.h), from a plan that caches
// (layers > 0): a moving camera or geometry evaluates every cached light without storing it
// (the frame before computed and stored them all: the plan of a first frame); one light moving
// first computes and stores its shade while the others are fetched, then evaluates it without
// storing. The cache's array id stands in for "reads" and "writes" (the GLSL depends on
// nothing else of them).
std::vector<ShadeCache::Plan> motionPlans(const ShadeCache::Plan& plan, unsigned cacheArray,
                                          const ExpectedMotion& motion) {
    std::vector<ShadeCache::Plan> plans;
    auto withSources = [&](int slot, ShadeCache::Source source) {
        ShadeCache::Plan changed = plan;
        bool fetches = false, computes = false;
        for (std::size_t other = 0; other < plan.sources.size(); ++other) {
            if (plan.channels[other] < 0) continue;
            changed.sources[other] =
                slot < 0 || static_cast<int>(other) == slot ? source : ShadeCache::Source::Fetch;
            fetches = fetches || changed.sources[other] == ShadeCache::Source::Fetch;
            computes = computes || changed.sources[other] == ShadeCache::Source::Compute;
        }
        changed.readArray = fetches ? cacheArray : 0;
        changed.writeArray = computes ? cacheArray : 0;
        return changed;
    };
    if (motion.cameraOrGeometry) plans.push_back(withSources(-1, ShadeCache::Source::Moving));
    for (const int slot : motion.lights)
        if (slot >= 0 && slot < static_cast<int>(plan.sources.size()) && plan.channels[slot] >= 0) {
            plans.push_back(withSources(slot, ShadeCache::Source::Compute));
            plans.push_back(withSources(slot, ShadeCache::Source::Moving));
        }
    return plans;
}

} // namespace

LitPass::LitPass(const RendererConfig& config, const RendererSwitches& switches)
    : config_(config), switches_(switches), programs_(config) {}

void LitPass::setWarmingUp(bool warmingUp, const ExpectedMotion& motion) {
    warmingUp_ = warmingUp;
    expectedMotion_ = warmingUp ? motion : ExpectedMotion{};
}

const LightVisibilityHook* LitPass::hookFor(const Frame& frame, const ShadeCache::Plan& plan, LitOutput output) const {
    const auto& hook = frame.lightVisibility();
    // The clustered pass has no per-light plan: every light it reaches is evaluated.
    if (frame.clusteredLights()) return hook ? &*hook : nullptr;
    // A shaded image that takes every light's shade from the cache needs none of the hook's
    // code: leaving it out spares llvmpipe its interpolated inputs and uniforms (measured:
    // 16.8 -> 15.7 ms for the showcase at 1280x720, whose unshadowed frame takes 14.0).
    return hook && (output != LitOutput::Color || plan.evaluatesHook()) ? &*hook : nullptr;
}

bool LitPass::compiledFor(const Frame& frame, const ShadeCache::Plan& plan, LitOutput output, const std::string& lights,
                          const std::vector<unsigned>& variants) const {
    const LightVisibilityHook* hook = hookFor(frame, plan, output);
    const std::string loadShades = plan.glsl();
    return std::all_of(variants.begin(), variants.end(), [&](unsigned variant) {
        return programs_.compiled(hook, lights, output, loadShades, variant) != nullptr;
    });
}

std::vector<LitPass::WarmUpDraw> LitPass::compileForMotion(const Frame& frame, const std::string& lights,
                                                           const std::vector<unsigned>& variants) {
    // Nothing cached: a moving frame's plan is this frame's.
    const std::vector<ShadeCache::Plan> bases =
        shadePlan_.layers > 0 ? motionPlans(shadePlan_, shadeCache_.currentArray(), expectedMotion_)
                               : std::vector{shadePlan_};
    std::vector<ShadeCache::Plan> plans;
    for (const ShadeCache::Plan& base : bases) {
        plans.push_back(base);
        if (!switches_.lightFootprints) continue;
        // Which lights a moving camera's split leaves out of a region changes as it moves:
        // every subset of the lights it may limit, while they are few; else this view's.
        const std::vector<int> limitable = footprintLimitableLights(frame.scene(), base);
        if (limitable.size() <= kMaxWarmedUpSplitLights) {
            for (unsigned subset = 1; subset < (1u << limitable.size()); ++subset) {
                std::vector<int> outside;
                for (std::size_t i = 0; i < limitable.size(); ++i)
                    if (subset & (1u << i)) outside.push_back(limitable[i]);
                plans.push_back(withoutLookups(base, outside));
            }
        } else {
            for (const auto& [rect, plan] : splitByLightFootprints(frame, base).regions) plans.push_back(plan);
        }
    }
    std::vector<WarmUpDraw> draws;
    for (const ShadeCache::Plan& plan : plans) {
        const LightVisibilityHook* hook = hookFor(frame, plan, LitOutput::Color);
        const std::string loadShades = plan.glsl();
        for (const unsigned variant : variants)
            draws.push_back({&programs_.programFor(hook, lights, LitOutput::Color, loadShades, variant), variant,
                             hook != nullptr, plan.writeArray != 0 ? plan.layers : 0, plan.readArray});
    }
    return draws;
}

void LitPass::addWarmUpPasses(Frame& frame, const std::vector<WarmUpDraw>& draws) {
    // One pass per set of outputs: a program that writes the shade cache's layers draws with
    // them attached, as in the frames that will use it.
    std::map<int, std::vector<WarmUpDraw>> byOutputs;
    for (const WarmUpDraw& draw : draws) byOutputs[draw.writtenLayers].push_back(draw);
    for (auto& [layers, group] : byOutputs) addWarmUpPass(frame, layers, std::move(group));
}

void LitPass::addWarmUpPass(Frame& frame, int writtenLayers, std::vector<WarmUpDraw> draws) {
    const auto& hook = frame.lightVisibility();
    const std::vector<float> dimming = lightDimming(frame);
    const std::string name = "lit_warm_up_" + std::to_string(writtenLayers);
    frame.graph().addPass(
        name,
        [&](PassBuilder& builder) {
            if (hook)
                for (ResourceHandle read : hook->reads) builder.read(read);
            const int samples = config_.msaa;
            PassTargets targets;
            targets.colors.push_back(
                {builder.create(name + "_color", {1, 1, kLitColorFormat, 1, false, samples}), -1, std::nullopt});
            targets.depth = DepthTarget{builder.create(name + "_depth", {1, 1, kLitDepthFormat, 1, false, samples}),
                                        -1, 1.0f};
            if (writtenLayers > 0) {
                // An array, as the cache's are even with one layer: llvmpipe compiles a program
                // again for a plain 2D target (measured: a 130 ms first frame of an orbiting sun).
                const ResourceHandle layers =
                    builder.create(name + "_shades", {1, 1, TextureFormat::RGBA32F, writtenLayers, false, 1, true});
                for (int layer = 0; layer < writtenLayers; ++layer) targets.colors.push_back({layers, layer, std::nullopt});
            }
            builder.setTargets(targets);
            PassState state;  // as the lit pass's
            state.srgbWrites = true;
            builder.setState(state);
            builder.sideEffect();  // what it draws is thrown away: it is drawn for the compiling
        },
        [this, &frame, draws = std::move(draws), dimming](PassContext& context) {
            const auto& hook = frame.lightVisibility();
            lights_.upload(frame.scene(), frame.camera());
            glBindBufferBase(GL_UNIFORM_BUFFER, kLightsUniformBinding, lights_.buffer());
            const Scene& scene = frame.scene();
            const glm::dmat4 view = glm::inverse(frame.camera().eyeToWorld);
            for (const WarmUpDraw& draw : draws) {
                draw.program->use();
                draw.program->set("uProjection", glm::mat4(frame.camera().projection));
                draw.program->set("uAmbient", config_.ambient);
                draw.program->set("uExposure", config_.exposure);
                draw.program->set("uMaskLight", -1);
                draw.program->set("uLightDimming", dimming);
                if (draw.evaluatesHook && hook && hook->bind) hook->bind(*draw.program, context);
                glBindTextureUnit(ShadeCache::kTextureUnit, draw.fetchedArray);
                // The first primitive of the program's material variant, drawn as the lit pass draws it.
                for (const MeshInstance& instance : scene.meshInstances) {
                    const SceneGpu::Primitive* found = nullptr;
                    for (const SceneGpu::Primitive& primitive : frame.gpu().primitives(instance))
                        if (materialFeatures(scene, frame.gpu(), primitive, MaterialUse::Shading) == draw.variant) {
                            found = &primitive;
                            break;
                        }
                    if (!found) continue;
                    const glm::dmat4 modelView = view * frame.gpu().modelMatrix(instance);
                    draw.program->set("uModelView", glm::mat4(modelView));
                    draw.program->set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(glm::dmat3(modelView)))));
                    draw.program->set("uReceiveShadows", 1);
                    applyMaterial(*draw.program, scene, frame.gpu(), *found, draw.variant, MaterialUse::Shading);
                    context.countDraw(frame.gpu().draw(*found));
                    break;
                }
            }
            glBindTextureUnit(ShadeCache::kTextureUnit, 0);
        });
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
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightsUniformBinding, lights_.buffer());
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

void LitPass::addPass(Frame& frame, const std::string& name, ResourceHandle target, LitOutput output,
                      int maskSlot) {
    const auto& hook = frame.lightVisibility();
    // The clustered pass loops over its tiles' lights: nothing is unrolled, cached per pixel
    // or split by footprints (the tiles are its footprints), and its programs are the same
    // whichever lights a frame sees, so there is nothing to warm up for motion.
    const bool clustered = frame.clusteredLights();
    const int lightCount =
        clustered ? 0 : std::min(static_cast<int>(frame.scene().lightInstances.size()), kMaxLights);
    // Only the shaded image uses the shade cache: the per-light views always ask the hook.
    if (output == LitOutput::Color) {
        const bool cacheable = switches_.shadeCache && hook && !clustered;
        shadePlan_ = cacheable ? shadeCache_.plan(shadeViewKey(frame, sceneGeneration_), *hook, lightCount,
                                                  frame.camera().width, frame.camera().height)
                               : ShadeCache::uncached(lightCount);
    }
    const bool color = output == LitOutput::Color;
    const std::string lights =
        clustered ? clusteredLightDefines() : lightDefines(frame.scene(), lightCount, switches_.unrolledLightSum);
    const std::vector<unsigned> variants = variantsInUse(frame.scene(), frame.gpu());
    // The shaded image may be split by light footprints, each region with a shade plan of its
    // own; the per-light views always ask the hook, everywhere.
    std::vector<std::pair<PixelRect, ShadeCache::Plan>> plans{
        {PixelRect::target(frame.camera().width, frame.camera().height),
         color ? shadePlan_ : ShadeCache::uncached(lightCount)}};
    if (color) {
        footprintLimitedLights_.clear();
        // A frame waits for the compiler only while warming up or when the whole target's
        // programs are new anyway: a split whose regions would need new programs is left out
        // otherwise (measured on the lamps' orbit: 1.1-1.5 s frames, each compiling 6).
        const bool mayCompile = warmingUp_ || !compiledFor(frame, shadePlan_, output, lights, variants);
        if (expectedMotion_.any() && !clustered) addWarmUpPasses(frame, compileForMotion(frame, lights, variants));
        if (switches_.lightFootprints && !clustered) {
            FootprintSplit split = splitByLightFootprints(frame, shadePlan_);
            const bool ready = mayCompile || std::all_of(split.regions.begin(), split.regions.end(), [&](const auto& region) {
                                   return compiledFor(frame, region.second, output, lights, variants);
                               });
            if (ready) {
                plans = std::move(split.regions);
                footprintLimitedLights_ = std::move(split.limitedLights);
            }
        }
        shadingRegionCount_ = static_cast<int>(plans.size());
    }
    std::vector<Region> regions;
    bool evaluatesHook = false;
    for (const auto& [rect, plan] : plans) {
        Region& region = regions.emplace_back();
        region.rect = rect;
        const LightVisibilityHook* regionHook = hookFor(frame, plan, output);
        region.evaluatesHook = regionHook != nullptr;
        evaluatesHook = evaluatesHook || region.evaluatesHook;
        const std::string loadShadesGlsl = plan.glsl();
        for (const unsigned variant : variants)
            region.programs[variant] = &programs_.programFor(regionHook, lights, output, loadShadesGlsl, variant);
    }
    const LightVisibilityHook* shading = evaluatesHook ? &*hook : nullptr;
    const std::vector<float> dimming = clustered && hook ? hook->dimming : lightDimming(frame);
    // Setup runs inside addPass, after both callbacks were built: share the handles it
    // declares with the execute callback through one small heap object.
    struct Handles { ResourceHandle target, depth; };
    auto handles = std::make_shared<Handles>();
    handles->target = target;
    const ShadeCache::Plan* shadePlan = color && shadePlan_.layers > 0 ? &shadePlan_ : nullptr;
    // Only the shaded image is multisampled: a per-light view's pixels are measured one by one.
    const int samples = color ? config_.msaa : 1;
    // The cache's layers are single-sampled outputs of this pass: decideSwitches turns the
    // cache off with multisampling.
    assert(samples == 1 || !shadePlan);
    frame.graph().addPass(
        name,
        [&](PassBuilder& builder) {
            if (shading)
                for (ResourceHandle read : shading->reads) builder.read(read);
            const int width = frame.camera().width, height = frame.camera().height;
            handles->depth = builder.create(name + "_depth", {width, height, kLitDepthFormat, 1, false, samples});
            // Multisampled, the pass draws into a transient of its own, resolved into `target` next.
            handles->target = samples > 1
                ? builder.create(name + "_multisampled", {width, height, kLitColorFormat, 1, false, samples})
                : builder.write(target);
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
        [this, &frame, regions, output, maskSlot, shading, shadePlan, dimming, clustered](PassContext& context) {
            if (clustered) uploadClusteredLights(frame, dimming);
            else if (output == LitOutput::Color) lights_.upload(frame.scene(), frame.camera());
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
    if (samples > 1) addResolvePass(frame, name + "_resolve", handles->target, target);
}

void LitPass::uploadClusteredLights(const Frame& frame, const std::vector<float>& dimming) {
    const FrameCamera& camera = frame.camera();
    lightTiles_ = buildLightTiles(lightFootprints(frame.scene(), camera), camera.width, camera.height, kLightTileSize);
    const LightTiles& tiles = lightTiles_;
    tileListEntries_ = static_cast<std::int64_t>(tiles.lights.size());
    longestTileList_ = 0;
    for (std::size_t tile = 0; tile + 1 < tiles.ranges.size(); tile += 2)
        longestTileList_ = std::max<int>(longestTileList_, static_cast<int>(tiles.ranges[tile + 1]));
    clusteredLights_.upload(frame.scene(), camera, dimming, tiles);
    clusteredLights_.bind();
}

void LitPass::addResolvePass(Frame& frame, const std::string& name, ResourceHandle drawn, ResourceHandle target) {
    struct Handles { ResourceHandle drawn, target; };
    auto handles = std::make_shared<Handles>();
    frame.graph().addPass(
        name,
        [&](PassBuilder& builder) {
            handles->drawn = builder.read(drawn);
            handles->target = builder.write(target);
            PassTargets targets;
            targets.colors.push_back({handles->target, -1, std::nullopt});
            builder.setTargets(targets);
            PassState state;
            state.depthTest = PassState::DepthTest::Off;
            // With sRGB writes on, the GL resolves an sRGB image in linear light: each pixel is
            // the coverage-weighted mean of its samples' tone-mapped radiance, then encoded.
            state.srgbWrites = true;
            builder.setState(state);
        },
        [this, handles](PassContext& context) {
            const TextureDesc& desc = context.desc(handles->drawn);
            const gl::Framebuffer& source = resolveSources_.get(
                {{GL_COLOR_ATTACHMENT0, context.texture(handles->drawn), -1}}, "multisampled image of pass \"" +
                                                                                  context.passName() + "\"");
            // The pass's declared target, bound by the graph's executor.
            GLint resolved = 0;
            glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &resolved);
            glBlitNamedFramebuffer(source.id(), static_cast<GLuint>(resolved), 0, 0, desc.width, desc.height, 0, 0,
                                   desc.width, desc.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        });
}

void LitPass::sceneChanged() {
    ++sceneGeneration_;
    shadeCache_.clear();
}

void LitPass::addTo(Frame& frame, ResourceHandle colorTarget) {
    addPass(frame, "lit", colorTarget, LitOutput::Color, -1);
}

void LitPass::addLightViewTo(Frame& frame, int slot, LightView view, ResourceHandle target) {
    const bool mask = view == LightView::ShadowMask;
    addPass(frame, (mask ? "shadow_mask_" : "shadow_compare_") + std::to_string(slot), target,
            mask ? LitOutput::ShadowMask : LitOutput::Comparison, slot);
}

} // namespace engine
