#include "plugin/AtlasMaps.h"

#include "plugin/DepthPasses.h"
#include "plugin/ShadowBlock.h"
#include "math/ScreenMatchedResolution.h"
#include "math/Texgen.h"
#include "technique/DepthFormatGl.h"
#include "technique/LightPlanner.h"
#include "technique/LookupParams.h"
#include "technique/NormalOffsetData.h"
#include "technique/Techniques.h"
#include "technique/UnseenShadows.h"

#include "engine/scene/FrustumCull.h"
#include "engine/scene/Scene.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmap {

namespace shaders {
extern const char shadow_data_glsl[];
extern const char moments_glsl[];
extern const char map_shapes_glsl[];
extern const char atlas_visibility_glsl[];
} // namespace shaders

namespace {

// The atlas is read on the clustered hook's first texture unit (compared) and the next (raw
// depth, for the comparison view); its lights' parameters on the third.
constexpr int kAtlasUnit = engine::kFirstClusteredPluginTextureUnit;
constexpr int kAtlasDepthUnit = engine::kFirstClusteredPluginTextureUnit + 1;
constexpr int kAtlasLightsUnit = engine::kFirstClusteredPluginTextureUnit + 2;
// The atlas hook's code never changes: one version for it, far from the per-layout versions
// the unrolled hook counts up from 1 (HookGlsl.h).
constexpr std::uint64_t kAtlasGlslVersion = std::numeric_limits<std::uint64_t>::max();

// atlas_visibility.glsl's AtlasLight, as its row of eight RGBA32F texels.
struct AtlasLight {
    glm::mat4 eyePlanes{0.0f};
    glm::vec4 rect{0.0f};
    glm::vec4 params{0.0f, 0.0f, 0.0f, 1.0f};
    glm::vec4 lightInEye{0.0f};
    glm::vec4 texel{0.0f};
};
static_assert(sizeof(AtlasLight) == 128);

bool heldByAtlas(const LightShadow& light) {
    return light.type == engine::Light::Type::Spot && light.frame.kind == MapKind::Map2D;
}

// The largest power of two not above n (n >= 1).
std::int64_t powerOfTwoBelow(std::int64_t n) {
    std::int64_t p = 1;
    while (p * 2 <= n) p *= 2;
    return p;
}

// Whether a ranged light's sphere of reach lies wholly outside the camera's frustum: then no
// pixel shows anything it lights (the tiles list it nowhere) and its map is not needed.
bool reachIsOffScreen(const LightShadow& light, const engine::Scene& scene, const glm::dmat4& cameraViewProjection) {
    const engine::LightInstance& placed = scene.lightInstances[light.slot];
    const double range = scene.lights[placed.light].range;
    if (light.type == engine::Light::Type::Directional || !(range > 0.0) || !std::isfinite(range)) return false;
    const glm::dvec3 centre = placed.position();
    return !engine::boxIntersectsFrustum(cameraViewProjection, {centre - glm::dvec3(range), centre + glm::dvec3(range)});
}

} // namespace

void AtlasMaps::reset() {
    requestedResolution_.clear();
    previousBlock_.clear();
    formatChosen_ = false;
}

bool AtlasMaps::conform(LightShadow& light, const Warn& warn) {
    ShadowSettings& settings = light.settings;
    if (settings.variant == Variant::Woo) {
        warn(light, "variant woo is not in the clustered pass's atlas yet (its peel reads a map of its own): "
                    "drawn as standard");
        settings.variant = Variant::Standard;
    }
    const MapLookup& lookup = mapLookupFor(settings);
    if (&lookup != &mapLookup(Filter::Pcf) && &lookup != &mapLookup(Filter::Nearest)) {
        warn(light, std::string("filter \"") + toString(settings.filter) +
                        (settings.filterRadius > 0.0 ? "\" with filter_radius" : "\"") +
                        " is not in the clustered pass's atlas yet: pcf instead");
        settings.filter = Filter::Pcf;
        settings.filterRadius = 0.0;
    }
    // The first light the atlas holds decides its format, depth direction and filter.
    if (!formatChosen_) {
        format_ = settings.depthFormat;
        reversedZ_ = settings.reversedZ;
        bilinear_ = mapLookupFor(settings).bilinearCompare();
        formatChosen_ = true;
    }
    if (settings.depthFormat != format_ || settings.reversedZ != reversedZ_) {
        warn(light, std::string("the clustered pass's atlas holds ") + toString(format_) +
                        (reversedZ_ ? " reversed-Z" : "") + " maps: this light's is one too");
        settings.depthFormat = format_;
        settings.reversedZ = reversedZ_;
    }
    if (mapLookupFor(settings).bilinearCompare() != bilinear_) {
        warn(light, std::string("the clustered pass's atlas is read with ") + (bilinear_ ? "pcf" : "nearest") +
                        ": this light's map too");
        settings.filter = bilinear_ ? Filter::Pcf : Filter::Nearest;
    }
    return true;
}

std::int64_t AtlasMaps::screenMatchedBlock(const LightShadow& light, const PlanContext& context) const {
    const int border = kAtlasLookupBorderTexels;
    // The cap: the block whose widest map is the largest not above the resolution asked for.
    const std::int64_t cap = std::max<std::int64_t>(powerOfTwoBelow(std::max(requestedResolution_[light.slot], 1) + 2 * border),
                                                    kMinAtlasBlock);
    const glm::dmat4 lightViewProjection = light.frame.view.viewProjection();
    const engine::Aabb reach = frustumBounds(lightViewProjection);
    if (reach.empty()) return cap;  // an infinite far plane: no bounded reach to measure
    const engine::FrameCamera& camera = context.camera;
    const double needed = screenMatchedResolution(lightViewProjection,
                                                  camera.projection * glm::inverse(camera.eyeToWorld), camera.width,
                                                  camera.height, receiverSamples(lightViewProjection, context.bounds.receivers));
    std::int64_t block = kMinAtlasBlock;
    while (block < cap && block - 2 * border < needed) block *= 2;
    // Hysteresis: a map shrinks only when the smaller block holds what it needs with
    // kShrinkMargin to spare, so a camera walking at a size's edge does not redraw it.
    const std::int64_t previous = light.slot < static_cast<int>(previousBlock_.size()) ? previousBlock_[light.slot] : 0;
    if (block < previous && previous <= cap) {
        while (block < previous && needed * kShrinkMargin > double(block - 2 * border)) block *= 2;
    }
    return block;
}

std::vector<AtlasRequest> AtlasMaps::requests(const std::vector<const LightShadow*>& held,
                                              const std::vector<const LightShadow*>& kept, const PlanContext& context) {
    const int border = kAtlasLookupBorderTexels;
    std::vector<std::int64_t> blocks;
    for (const LightShadow* light : held) blocks.push_back(screenMatchedBlock(*light, context));
    for (const LightShadow* light : kept) blocks.push_back(previousBlock_[light->slot]);
    std::vector<const LightShadow*> all = held;
    all.insert(all.end(), kept.begin(), kept.end());
    const std::int64_t capacity = std::int64_t(kMaxAtlasSize) * kMaxAtlasSize;
    auto area = [&] {
        std::int64_t sum = 0;
        for (const std::int64_t block : blocks) sum += block * block;
        return sum;
    };
    // Too many texels asked for: the largest blocks halve first (the last of equals, so the
    // first lights keep theirs), until every map fits.
    while (area() > capacity) {
        const auto largest = std::max_element(blocks.rbegin(), blocks.rend());
        if (*largest <= kMinAtlasBlock) break;
        *largest /= 2;
    }
    std::vector<AtlasRequest> out;
    previousBlock_.assign(requestedResolution_.size(), 0);
    for (std::size_t i = 0; i < all.size(); ++i) {
        out.push_back({{all[i]->slot, 0}, static_cast<int>(blocks[i]) - 2 * border});
        previousBlock_[all[i]->slot] = blocks[i];
    }
    return out;
}

void AtlasMaps::ensureTexture(int size) {
    const GLenum format = glInternalFormat(format_);
    if (texture_.id() && texture_.width() == size && static_cast<GLenum>(texture_.internalFormat()) == format) return;
    texture_ = engine::gl::Texture::create2D(format, size, size);
    texture_.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    texture_.setParameter(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    texture_.setParameter(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    allocator_.emplace(size, kAtlasLookupBorderTexels);  // a new texture holds no map
}

engine::ResourceHandle AtlasMaps::addPasses(engine::Frame& frame, std::vector<LightShadow>& lights,
                                            const PlanContext& context, DepthRenderer& renderer,
                                            const std::vector<bool>& closedMeshes, const CasterLods* casterLods,
                                            std::vector<std::vector<std::uint64_t>>& levelDraws,
                                            std::uint64_t sceneGeneration, bool cacheMaps, const Warn& warn) {
    counts_ = {};
    if (requestedResolution_.size() < lights.size()) {
        requestedResolution_.resize(lights.size(), 0);
        for (const LightShadow& light : lights) requestedResolution_[light.slot] = light.settings.resolution;
    }
    std::vector<const LightShadow*> held, kept;
    const glm::dmat4 cameraViewProjection = context.camera.projection * glm::inverse(context.camera.eyeToWorld);
    for (LightShadow& light : lights) {
        if (reachIsOffScreen(light, context.scene, cameraViewProjection)) {
            // Nothing it lights is seen: no planning (its fit alone costs tens of
            // microseconds among many boxes), and a map it has keeps its block and contents
            // for when it comes back into view.
            light.frame = {};
            light.frame.skipReason = "its range is off screen";
            if (light.slot < static_cast<int>(previousBlock_.size()) && previousBlock_[light.slot] > 0)
                kept.push_back(&light);
            continue;
        }
        // Texture units are not the limit here: one unit serves every map.
        if (!planLight(light, context, kAtlasUnit, std::numeric_limits<int>::max())) continue;
        if (!heldByAtlas(light)) {
            warn(light, std::string("no shadow: the clustered pass's atlas holds spot lights' maps only so far (this "
                                    "light's is a ") + mapProjection(light.frame.kind)->name() + " map)");
            light.frame.kind = MapKind::None;
            continue;
        }
        if (conform(light, warn)) held.push_back(&light);
    }
    if (held.empty()) return {};
    const std::vector<AtlasRequest> wanted = requests(held, kept, context);
    std::int64_t blockArea = 0;
    for (const AtlasRequest& request : wanted) {
        const std::int64_t block = request.size + 2 * kAtlasLookupBorderTexels;
        blockArea += block * block;
    }
    int size = 4;
    while (std::int64_t(size) * size < blockArea && size < kMaxAtlasSize) size *= 2;
    // Grown only: a shrinking atlas would draw every map again for a few texels.
    if (texture_.id()) size = std::max(size, texture_.width());
    ensureTexture(size);
    const AtlasFrameReport& report = allocator_->allocate(wanted);
    std::vector<bool> drawnAgain(lights.size(), false);
    for (const auto* list : {&report.placed, &report.moved})
        for (const AtlasKey& key : *list) drawnAgain[key.light] = true;

    engine::ResourceHandle atlas = frame.graph().importTexture(
        "shadow_atlas", {size, size, graphFormat(format_)}, texture_.id());
    for (std::size_t i = 0; i < held.size(); ++i) {
        LightShadow& light = lights[held[i]->slot];
        const std::optional<AtlasPlacement> placement = allocator_->find({light.slot, 0});
        if (!placement) {  // requests() fits every map, so this is not expected; still no nonsense
            warn(light, "no shadow: no room left in the clustered pass's atlas");
            light.frame.kind = MapKind::None;
            continue;
        }
        light.settings.resolution = placement->map.size;
        if (drawnAgain[light.slot]) light.renderedKey = 0;  // its rectangle holds nothing of it yet
        planUnseenShadows(light, context);
        decideCache(light, frame.scene(), sceneGeneration, cacheMaps);
        keepCachedMapsThatHoldTheNeededCasters(light);
        if (light.frame.cacheHit) {
            ++counts_.cached;
        } else {
            ++counts_.rendered;
            addDepthPasses(light, frame, atlas, renderer, closedMeshes, casterLods, levelDraws[light.slot],
                           {placement->map.x, placement->map.y, placement->map.size});
        }
    }
    for (const LightShadow* light : held) lights[light->slot].frame.map = atlas;
    return atlas;
}

engine::LightVisibilityHook AtlasMaps::hook(const engine::Frame& frame, const std::vector<LightShadow>& lights,
                                            engine::ResourceHandle atlas) {
    const glm::dmat4& eyeToWorld = frame.camera().eyeToWorld;
    const glm::dmat4 worldToEye = glm::inverse(eyeToWorld);
    const int size = texture_.id() ? texture_.width() : 1;
    std::vector<AtlasLight> data(frame.scene().lightInstances.size());
    engine::LightVisibilityHook hook;
    hook.owner = kPluginName;
    hook.dimming.assign(data.size(), 0.0f);
    for (const LightShadow& light : lights) {
        AtlasLight& entry = data[light.slot];
        const std::optional<AtlasPlacement> placement =
            allocator_ && light.frame.kind == MapKind::Map2D ? allocator_->find({light.slot, 0}) : std::nullopt;
        if (!placement) {
            // No map: lit everywhere, or nowhere for a spot whose frustum holds nothing visible.
            entry.params.w = light.frame.emptyFrustum && light.type == engine::Light::Type::Spot ? 0.0f : 1.0f;
            continue;
        }
        const LightView& view = light.frame.view;
        const glm::mat4 planes(eyePlanesForCamera(view.texgenPlanes(), eyeToWorld));
        if (!std::all_of(&planes[0][0], &planes[0][0] + 16, [](float v) { return std::isfinite(v); })) continue;
        entry.eyePlanes = planes;
        entry.rect = glm::vec4(placement->map.x, placement->map.y, placement->map.size, placement->map.size) /
                     static_cast<float>(size);
        // As ShadowHook's params: the reference bias that d32f without reversed Z needs.
        const bool floatForward = light.settings.depthFormat == DepthFormat::D32F && !light.settings.reversedZ;
        const float referenceBias =
            floatForward ? static_cast<float>(std::abs(light.settings.effectivePolygonOffset().y) * std::ldexp(1.0, -24))
                         : 0.0f;
        entry.params = glm::vec4(light.settings.reversedZ ? 1.0f : 0.0f, referenceBias,
                                 lookupParams(light.settings).w, 0.0f);  // outside a spot's map: outside its cone
        entry.lightInEye = lightInEye(view, light.type, worldToEye);
        entry.texel = glm::vec4(texelWidthPerDepth(view, light.settings.resolution),
                                texelWidthPerDepthSquared(view, light.settings.resolution), 0.5f / size, 1.0f);
        hook.dimming[light.slot] = light.settings.dimming;
    }
    const int rows = std::max(static_cast<int>(data.size()), 1);
    if (!lightData_.id() || lightData_.height() < rows) {
        int height = 1;
        while (height < rows) height *= 2;
        lightData_ = engine::gl::Texture::create2D(GL_RGBA32F, sizeof(AtlasLight) / sizeof(glm::vec4), height);
        lightData_.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        lightData_.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    if (!data.empty())
        glTextureSubImage2D(lightData_.id(), 0, 0, 0, sizeof(AtlasLight) / sizeof(glm::vec4),
                            static_cast<int>(data.size()), GL_RGBA, GL_FLOAT, data.data());
    if (texture_.id()) {
        texture_.setParameter(GL_TEXTURE_COMPARE_FUNC, reversedZ_ ? GL_GEQUAL : GL_LEQUAL);
        const GLint filter = bilinear_ ? GL_LINEAR : GL_NEAREST;
        texture_.setParameter(GL_TEXTURE_MIN_FILTER, filter);
        texture_.setParameter(GL_TEXTURE_MAG_FILTER, filter);
    }
    hook.glsl = shadowBlockGlslDefines() + "#define ATLAS_LIGHTS_UNIT " + std::to_string(kAtlasLightsUnit) +
                "\n#define ATLAS_UNIT " + std::to_string(kAtlasUnit) + "\n#define ATLAS_DEPTH_UNIT " +
                std::to_string(kAtlasDepthUnit) + "\n" + shaders::shadow_data_glsl + shaders::moments_glsl +
                shaders::map_shapes_glsl + shaders::atlas_visibility_glsl;
    hook.glslVersion = kAtlasGlslVersion;
    if (atlas.valid()) hook.reads.push_back(atlas);
    if (!rawDepthSampler_.id()) {  // the comparison view reads depths, not comparisons
        rawDepthSampler_ = engine::gl::Sampler::create();
        rawDepthSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
        rawDepthSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        rawDepthSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    const unsigned lightData = lightData_.id(), texture = texture_.id(), rawSampler = rawDepthSampler_.id();
    hook.bind = [lightData, texture, rawSampler](const engine::gl::Program&, const engine::PassContext&) {
        glBindTextureUnit(kAtlasLightsUnit, lightData);
        glBindSampler(kAtlasLightsUnit, 0);
        glBindTextureUnit(kAtlasUnit, texture);
        glBindSampler(kAtlasUnit, 0);
        glBindTextureUnit(kAtlasDepthUnit, texture);
        glBindSampler(kAtlasDepthUnit, rawSampler);
    };
    return hook;
}

nlohmann::json AtlasMaps::stats() const {
    if (!allocator_) return nullptr;
    return {{"size", allocator_->atlasSize()},
            {"maps", allocator_->placements().size()},
            {"occupancy", allocator_->occupancy()},
            {"rendered", counts_.rendered},
            {"cached", counts_.cached},
            {"repacked", allocator_->lastFrame().repacked}};
}

} // namespace shadowmap
