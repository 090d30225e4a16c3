#include "plugin/ShadowHook.h"

#include "plugin/ShadowBlock.h"
#include "technique/LookupParams.h"
#include "technique/Techniques.h"

#include "engine/scene/Scene.h"
#include "engine/util/Hasher.h"

#include <epoxy/gl.h>

#include <cmath>
#include <map>

namespace shadowmap {

namespace {
constexpr int kFirstUnit = engine::kFirstPluginTextureUnit;
} // namespace

engine::LightVisibilityHook ShadowHook::build(const engine::Frame& frame, const std::vector<LightShadow>& lights,
                                              bool cacheMaps, int maxTextureUnits, const Warn& warn) {
    const glm::dmat4& eyeToWorld = frame.camera().eyeToWorld;  // V
    const LookupContext context{frame.scene(), eyeToWorld, glm::inverse(eyeToWorld)};
    // Lights without a map this frame: fully visible, nothing dimmed.
    ShadowBlock block{};
    glm::vec4* params = block.params;
    for (int slot = 0; slot < engine::kMaxLights; ++slot) {
        params[slot] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        block.pointFar[slot].x = 1.0f;
    }
    block.eyeToWorld = glm::mat4(glm::mat3(glm::dmat3(eyeToWorld)));
    std::vector<std::pair<int, unsigned>> units;      // texture unit, map (comparing) or moments
    // texture unit, map read as raw depth: the comparison view's, and the lookups' that
    // compare depths themselves
    std::vector<std::pair<int, unsigned>> rawUnits;
    std::vector<std::uint64_t> shadeKeys(lights.size(), 0);  // 0: not to be reused
    // A light without a map this frame has one shade everywhere (1, or 0 for a spot light
    // whose frustum holds nothing visible): the lit pass needs no lookup for it.
    std::map<int, float> constantShades;

    // What the generated GLSL depends on: per shadowed light its slot, map kind, lookup
    // functions and whether its comparison view has a texture unit.
    std::vector<HookGlsl::Lookup> lookups;
    for (const LightShadow& light : lights) {
        if (light.slot >= engine::kMaxLights) break;  // past what the unrolled lit pass renders
        const LightShadowFrame& plan = light.frame;
        // Outside a spot light's frustum is outside its cone: never lit by it. Directional
        // frusta hold every visible receiver, so what lies outside has nothing to fear.
        const float outsideShade = light.type == engine::Light::Type::Spot ? 0.0f : 1.0f;
        if (plan.kind == MapKind::Screen) {
            // volume: the visibility texture, read at the pixel; nothing to project or bias.
            const int unit = kFirstUnit + light.slot;
            params[light.slot] = glm::vec4(0.0f, 0.0f, light.settings.dimming, 1.0f);
            if (cacheMaps) shadeKeys[light.slot] = plan.mapKey;
            units.emplace_back(unit, light.visibility.id());
            HookGlsl::Lookup lookup{light.slot, unit, false, -1, 0, toString(Variant::Volume)};
            lookup.screen = true;
            lookups.push_back(lookup);
            continue;
        }
        const MapProjection* projection = mapProjection(plan.kind);
        if (!projection) {
            if (plan.emptyFrustum) params[light.slot] = glm::vec4(0.0f, 0.0f, 0.0f, outsideShade);
            constantShades[light.slot] = params[light.slot].w;
            continue;
        }
        const int unit = kFirstUnit + light.slot;
        // The comparison view reads the same map's raw depth on a second unit, through a
        // sampler object with comparison off, when the GL has units to spare: counted down
        // from the last unit, above every light's comparing unit.
        const int rawUnit = maxTextureUnits - 1 - light.slot;
        const bool debuggable = rawUnit >= kFirstUnit + static_cast<int>(lights.size());
        const MapLookup& mapLookup = shadowmap::mapLookupFor(light.settings);
        HookGlsl::Lookup lookup{light.slot, unit, false, debuggable ? rawUnit : -1, 0, mapLookup.glslName()};
        if (!projection->packLookup(light, context, block, lookup)) {
            warn(light, "no shadow: its texgen planes for this camera are not finite");
            constantShades[light.slot] = params[light.slot].w;
            continue;
        }
        // x: 1 = reversed Z (near 1, far 0: GL_GEQUAL, out of range flipped);
        // y: reference bias subtracted from r: d32f without reversed Z computes r near 1 with
        //    an absolute float error, which float polygon-offset units (relative) do not
        //    cover below depth 0.5; units * 2^-24 restores the d24 meaning of units there
        //    (shadowmap/ShadowSettings.h).
        const bool floatForward = light.settings.depthFormat == DepthFormat::D32F && !light.settings.reversedZ;
        const float referenceBias =
            floatForward ? static_cast<float>(std::abs(light.settings.effectivePolygonOffset().y) * std::ldexp(1.0, -24))
                         : 0.0f;
        params[light.slot] = glm::vec4(light.settings.reversedZ ? 1.0f : 0.0f, referenceBias,
                                       light.settings.dimming, outsideShade);
        // The lit pass may reuse this light's shade per pixel while this key (and the camera
        // and geometry, which the engine adds) holds: the map's content and how it is read.
        engine::Hasher shadeKey;
        shadeKey.add(plan.mapKey);
        shadeKey.add(params[light.slot]);
        mapLookup.addShadeKey(shadeKey);
        projection->addShadeKey(light, shadeKey);
        block.lookupParams[light.slot] = lookupParams(light.settings);
        shadeKey.add(block.lookupParams[light.slot]);
        shadeKey.add(block.texelWidths[light.slot]);
        shadeKey.add(block.lightInEye[light.slot]);
        for (int layer = 0; layer < kMaxCascades; ++layer) shadeKey.add(block.softLayers[light.slot * kMaxCascades + layer]);
        // Without map caching nothing is reused: a depth pass whose map no pass reads
        // would be culled, and timing runs (bench, cache_maps false) would time nothing.
        if (cacheMaps) shadeKeys[light.slot] = shadeKey.value();
        // A moments lookup reads the moments through their own (filtering) state.
        if (mapLookup.momentChannels() > 0) units.emplace_back(unit, light.moments.id());
        else (mapLookup.comparesInHardware() ? units : rawUnits).emplace_back(unit, light.map.id());
        if (debuggable) rawUnits.emplace_back(rawUnit, light.map.id());
        lookups.push_back(lookup);
    }

    engine::LightVisibilityHook hook;
    hook.owner = kPluginName;
    hook.constantShades = std::move(constantShades);
    hook.shadeKeys = std::move(shadeKeys);
    for (const glm::vec4& light : block.params) hook.dimming.push_back(light.z);
    const HookGlsl::Code& code = hookGlsl_.codeFor(lookups);
    hook.glsl = code.fragment;
    hook.vertexGlsl = code.vertex;
    hook.glslVersion = code.version;
    // Uploaded now, before any pass of the frame runs (GL keeps the order), once for every
    // program variant of the frame.
    if (!shadowBlock_.id())
        shadowBlock_ = engine::gl::Buffer::create(sizeof(ShadowBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(shadowBlock_.id(), 0, sizeof(ShadowBlock), &block);
    const unsigned rawSampler = rawDepthSampler().id();
    const unsigned blockBuffer = shadowBlock_.id();
    hook.bind = [=](const engine::gl::Program&, const engine::PassContext&) {
        glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, blockBuffer);
        // Sampler 0: the map's own comparing state, whatever sampler the unit held before
        // (a light that was read raw on it in an earlier frame or pass).
        for (const auto& [unit, map] : units) {
            glBindTextureUnit(unit, map);
            glBindSampler(unit, 0);
        }
        for (const auto& [unit, map] : rawUnits) {
            glBindTextureUnit(unit, map);
            glBindSampler(unit, rawSampler);
        }
    };
    return hook;
}

const engine::gl::Sampler& ShadowHook::rawDepthSampler() {
    if (!rawDepthSampler_.id()) {
        rawDepthSampler_ = engine::gl::Sampler::create();
        rawDepthSampler_.set(GL_TEXTURE_COMPARE_MODE, GL_NONE);
        rawDepthSampler_.set(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        rawDepthSampler_.set(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        rawDepthSampler_.set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        rawDepthSampler_.set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return rawDepthSampler_;
}

} // namespace shadowmap
