#include "engine/render/Renderer.h"

#include "engine/gl/GlError.h"
#include "engine/render/GlPassState.h"
#include "engine/render/TextureReadback.h"
#include "engine/scene/Scene.h"
#include "engine/util/Error.h"

#include <algorithm>
#include <chrono>

namespace engine {

int maxMsaaSamples() {
    int most = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    for (const TextureFormat format : {kLitColorFormat, kLitDepthFormat}) {
        // GL_SAMPLES lists the counts in decreasing order: the first is the format's maximum.
        GLint counts = 0, first = 0;
        const GLenum internal = internalFormatFor(format);
        glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internal, GL_NUM_SAMPLE_COUNTS, 1, &counts);
        if (counts > 0) glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internal, GL_SAMPLES, 1, &first);
        most = std::min(most, static_cast<int>(first));
    }
    return most;
}

namespace {

// Which lights the shaded image took from the shade cache, which it recomputed (and
// cached), which it evaluated without storing because they keep changing, which it
// evaluated without caching and which had one shade everywhere, by slot.
ShadeCacheReport shadeCacheReport(const ShadeCache::Plan& plan) {
    ShadeCacheReport report;
    report.layers = plan.layers;
    for (int slot = 0; slot < static_cast<int>(plan.sources.size()); ++slot) {
        switch (plan.sources[slot]) {
        case ShadeCache::Source::Fetch: report.fetched.push_back(slot); break;
        case ShadeCache::Source::Compute: report.computed.push_back(slot); break;
        case ShadeCache::Source::Moving: report.moving.push_back(slot); break;
        case ShadeCache::Source::Inline: report.uncached.push_back(slot); break;
        case ShadeCache::Source::Constant: report.constant.push_back(slot); break;
        }
    }
    return report;
}

// GL_RENDERER of the current context ("" without one).
std::string currentGlRenderer() {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return text ? text : "";
}

// An error, not a clamp: a user who asks for 8 samples and silently gets 4 gets a different
// image from the same config on another machine, and cannot tell why; the message names the
// most this GL offers, so the fix is one edit.
void requireSupportedMsaa(const RendererConfig& config, const std::string& glRenderer) {
    if (config.msaa <= 1) return;
    const int most = maxMsaaSamples();
    if (config.msaa <= most) return;
    int allowed = 1;  // the largest count renderer.msaa accepts that this GL offers
    for (const int samples : kMsaaSampleCounts)
        if (samples <= most) allowed = std::max(allowed, samples);
    throwInputError("", "renderer.msaa",
                    std::to_string(config.msaa) + " samples asked for, but " +
                        (glRenderer.empty() ? std::string("this GL") : glRenderer) + " offers at most " +
                        std::to_string(most) + " for the shaded image's targets; use " + std::to_string(allowed) +
                        " or less");
}

// The config, checked against the current context.
const RendererConfig& supportedConfig(const RendererConfig& config) {
    requireSupportedMsaa(config, currentGlRenderer());
    return config;
}

} // namespace

Renderer::Renderer(const RendererConfig& config, std::vector<RenderPlugin*> plugins)
    : config_(supportedConfig(config)),
      switches_(decideSwitches(config, currentGlRenderer())),
      plugins_(std::move(plugins)),
      litPass_(std::make_unique<LitPass>(config, switches_)) {}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene) {
    scene_ = &scene;
    gpu_ = std::make_unique<SceneGpu>(scene);
    litPass_->sceneChanged();
    for (RenderPlugin* plugin : plugins_) plugin->prepareScene(scene);
}

const gl::Texture& Renderer::lightViewTarget(LitPass::LightView view, int slot, int width, int height) {
    gl::Texture& texture = lightViews_[{view, slot}];
    if (!texture.id() || texture.width() != width || texture.height() != height)
        texture = gl::Texture::create2D(GL_RGBA8, width, height);
    return texture;
}

void Renderer::reloadSettings() {
    for (RenderPlugin* plugin : plugins_) plugin->reloadSettings(*scene_);
}

int Renderer::warmUp(const FrameRequest& request, int minFrames, int maxFrames, const ExpectedMotion& motion) {
    FrameRequest untimed = request;
    untimed.timing = false;
    int frames = 0;
    litPass_->setWarmingUp(true, motion);
    while (frames < maxFrames) {
        const FrameResult result = renderFrame(untimed);
        ++frames;
        if (frames >= minFrames && result.programsLinked == 0) break;
    }
    litPass_->setWarmingUp(false);
    // Untimed frames are not waited for: without this the first timed pass's glFinish would
    // wait for the warm-up frames' rasterizing still queued (llvmpipe runs it in threads).
    glFinish();
    return frames;
}

FrameResult Renderer::renderFrame(const FrameRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t linkedBefore = gl::Program::linkedCount();
    const int width = request.camera.width, height = request.camera.height;
    if (!color_.id() || color_.width() != width || color_.height() != height)
        color_ = gl::Texture::create2D(internalFormatFor(kLitColorFormat), width, height);

    // Skinned and morphed instances posed since the last frame (the scene is the caller's).
    gpu_->updateDeformed(*scene_);
    RenderGraph graph;
    const bool clustered = usesClusteredLights(config_.clusteredLights, scene_->lightInstances.size());
    Frame frame(*scene_, *gpu_, graph, request.camera, frameIndex_++, clustered);
    frame.setMapReadbackSlots(request.shadowMapSlots);
    const ResourceHandle color =
        graph.importTexture("scene_color", {width, height, kLitColorFormat}, color_.id());
    for (RenderPlugin* plugin : plugins_) {
        // A plugin's bad pass declaration (unknown resource, second writer...) is the
        // plugin's fault, not the scene's: say which plugin, not only which pass.
        try {
            plugin->addPasses(frame);
        } catch (const InputError&) {
            throw;
        } catch (const std::exception& error) {
            throw PluginError("plugin \"" + plugin->name() + "\": " + error.what());
        }
    }
    litPass_->addTo(frame, color);
    graph.markOutput(color);
    const auto addLightViews = [&](const std::vector<int>& slots, LitPass::LightView view) {
        for (int slot : slots) {
            const gl::Texture& texture = lightViewTarget(view, slot, width, height);
            const std::string kind = view == LitPass::LightView::ShadowMask ? "mask" : "compare";
            const ResourceHandle target =
                graph.importTexture("shadow_" + kind + "_target_" + std::to_string(slot),
                                    {width, height, TextureFormat::RGBA8}, texture.id());
            litPass_->addLightViewTo(frame, slot, view, target);
            graph.markOutput(target);
        }
    };
    addLightViews(request.shadowMaskSlots, LitPass::LightView::ShadowMask);
    addLightViews(request.comparisonSlots, LitPass::LightView::Comparison);

    graph.compile();
    ExecuteOptions options;
    options.timing = request.timing;
    options.finish = [] { glFinish(); };
    options.applyState = applyPassState;
    options.bindTargets = [this](const PassTargets& targets, const PassState& state, const PassContext& context) {
        targets_.bind(targets, state, context);
    };
    if (config_.checkGlErrors) {
        gl::checkGlError("the start of the frame (a call made before renderFrame)");
        options.afterPass = [](const std::string& pass) { gl::checkGlError(("pass \"" + pass + "\"").c_str()); };
    }
    graph.execute(pool_, options);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    pool_.endFrame();  // textures of an old setting or size are freed, not kept forever
    PassState afterFrame;  // tools drawing after the frame start from the defaults too
    afterFrame.viewportWidth = width;
    afterFrame.viewportHeight = height;
    applyPassState(afterFrame);
    // Untimed frames are not waited for: the readbacks below and the caller's swap or
    // readPixels synchronise with the GPU when they need the results.
    if (request.timing) glFinish();

    FrameResult result;
    result.shadowViews = frame.shadowViews();
    for (const int slot : request.shadowMapSlots) {
        const ShadowView* view = result.shadowView(slot);
        if (view && view->hasScreenVisibility && view->stencilCount.valid()) {
            const std::uint32_t texture = graph.importedPhysical(view->stencilCount);
            const TextureDesc& desc = graph.descOf(view->stencilCount);
            if (texture && desc.format == TextureFormat::R8)
                result.stencilCounts[slot] = {desc.width, desc.height, readR8TopDown(texture, desc.width, desc.height)};
        }
        if (!view || !view->hasMap) continue;
        const ResourceHandle resource = view->map;
        const std::uint32_t texture = graph.importedPhysical(resource);
        if (!texture || !isDepthFormat(graph.descOf(resource).format)) continue;
        const TextureDesc& desc = graph.descOf(resource);
        DepthReadback& readback = result.shadowMaps[slot];
        readback.width = desc.width;
        readback.height = desc.height;
        readback.cube = desc.cube;
        readback.layers = desc.cube ? kCubeFaces : desc.layers;
        readback.depth = readDepthLayersTopDown(texture, desc.width, desc.height, readback.layers);
    }
    result.passes = graph.reports();
    result.graphviz = graph.graphviz();
    result.shadowTermProvided = frame.lightVisibility().has_value();
    result.litInstancesCulled = litPass_->culledInstances();
    result.shadeCache = shadeCacheReport(litPass_->shadePlan());
    result.footprintLimitedLights = litPass_->footprintLimitedLights();
    result.shadingRegions = litPass_->shadingRegionCount();
    result.clusteredLights = frame.clusteredLights();
    result.tileListEntries = litPass_->tileListEntries();
    result.longestTileList = litPass_->longestTileList();
    if (result.clusteredLights) {
        const LightTiles& tiles = litPass_->lightTiles();
        result.tileColumns = tiles.columns;
        result.tileRows = tiles.rows;
        for (std::size_t tile = 0; tile + 1 < tiles.ranges.size(); tile += 2)
            result.tileLightCounts.push_back(tiles.ranges[tile + 1]);
    }
    for (RenderPlugin* plugin : plugins_) result.pluginStats[plugin->name()] = plugin->frameStats();
    result.programsLinked = static_cast<int>(gl::Program::linkedCount() - linkedBefore);
    result.frameMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::vector<std::uint8_t> Renderer::readColor() const {
    return readTextureRGBA8TopDown(color_);
}

std::vector<std::uint8_t> Renderer::readShadowMask(int slot) const {
    const auto found = lightViews_.find({LitPass::LightView::ShadowMask, slot});
    if (found == lightViews_.end()) return {};
    const std::vector<std::uint8_t> rgba = readTextureRGBA8TopDown(found->second);
    std::vector<std::uint8_t> gray(rgba.size() / 4);
    for (std::size_t i = 0; i < gray.size(); ++i) gray[i] = rgba[i * 4];
    return gray;
}

std::vector<std::uint8_t> Renderer::readComparison(int slot) const {
    const auto found = lightViews_.find({LitPass::LightView::Comparison, slot});
    return found == lightViews_.end() ? std::vector<std::uint8_t>{} : readTextureRGBA8TopDown(found->second);
}

nlohmann::json ShadeCacheReport::toJson() const {
    return {{"layers", layers},     {"fetched", fetched},   {"computed", computed},
            {"moving", moving},     {"uncached", uncached}, {"constant", constant}};
}

double FrameResult::shadowPassMs(const ShadowView& view, bool& ran) const {
    double total = 0.0;
    ran = false;
    for (const PassId id : view.passes) {
        const PassReport& pass = passes.at(id.index);
        if (pass.culled) continue;
        total += pass.wallMs;
        ran = true;
    }
    return total;
}

FrameResult::PassWork FrameResult::shadowPassWork(const ShadowView& view) const {
    PassWork work;
    for (const PassId id : view.passes) {
        work.draws += passes.at(id.index).draws;
        work.triangles += passes.at(id.index).triangles;
        work.drawsCulled += passes.at(id.index).drawsCulled;
    }
    return work;
}

const ShadowView* FrameResult::shadowView(int slot) const {
    for (const ShadowView& view : shadowViews)
        if (view.slot == slot) return &view;
    return nullptr;
}

} // namespace engine
