#include "plugin/ShadowMapPlugin.h"

#include "plugin/DepthPasses.h"
#include "plugin/MomentsPasses.h"
#include "plugin/VolumePasses.h"
#include "technique/DepthFormatGl.h"
#include "technique/LightPlanner.h"
#include "technique/Techniques.h"
#include "technique/UnseenShadows.h"

#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <epoxy/gl.h>

#include <cmath>
#include <iostream>

namespace shadowmap {

bool ShadowMapPlugin::setLightOption(const std::string& light, const std::string& key, const nlohmann::json& value) {
    // Checked alone now, so a bad key or value is refused before any GL work; checked again
    // combined with the light's other settings in resolveLights (reversed_z needs d32f...).
    const nlohmann::json option = {{key, value}};
    ShadowSettings scratch;
    applySettings(scratch, option, "", "light \"" + light + "\"");
    lightOptions_[light][key] = value;
    return true;
}

nlohmann::json ShadowMapPlugin::sceneLightSettings(const engine::Scene& scene, int slot) const {
    const engine::Light& light = scene.lights[scene.lightInstances[slot].light];
    if (light.extras.is_object() && light.extras.contains("shadow") && light.extras["shadow"].is_object())
        return light.extras["shadow"];
    return nlohmann::json::object();
}

void ShadowMapPlugin::resolve(const engine::Scene& scene) {
    GLint maxTextureSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &maxTextureUnits_);
    scenePath_ = scene.sourcePath;
    lights_ = resolveLights(scene, defaults_, lightOptions_, maxTextureSize,
                            [this](const LightState& light, const std::string& message) { warnOnce(light, message); });
    closedMeshes_ = closedCasterMeshes(scene);
}

void ShadowMapPlugin::prepareScene(const engine::Scene& scene) {
    resolve(scene);
    ++sceneGeneration_;  // new geometry: no map is still right
    atlas_.reset();
    volumes_.reset();      // its meshes' adjacency is the old scene's
    casterLods_.reset();   // the old scene's meshes
    cacheHits_ = cacheMisses_ = 0;
}

void ShadowMapPlugin::reloadSettings(const engine::Scene& scene) {
    std::vector<LightShadow> previous = std::move(lights_);
    resolve(scene);
    atlas_.reset();
    // Keep each light's map: its cache key covers the settings, so a light whose settings
    // changed misses and re-renders, and the others keep hitting.
    for (LightShadow& light : lights_)
        for (LightShadow& old : previous)
            if (old.slot == light.slot) {
                light.map = std::move(old.map);
                light.moments = std::move(old.moments);
                light.mapLayers = std::move(old.mapLayers);
                light.renderedKey = old.renderedKey;
                light.visibility = std::move(old.visibility);
                light.visibilityKey = old.visibilityKey;
                light.renderedUnseen = std::move(old.renderedUnseen);  // what that map lacks
            }
}

void ShadowMapPlugin::warnOnce(const LightState& light, const std::string& message) {
    // Once per scene file, light and message for the plugin's life: a sweep that sets the
    // same scene again for every setting (shadowmap-bench) must not repeat itself.
    const std::string line = std::string(kPluginName) + ": " + scenePath_ + ": light \"" + light.name + "\": " + message;
    if (warned_.insert(line).second) std::cerr << "warning: " << line << "\n";
}

void ShadowMapPlugin::addPasses(engine::Frame& frame) {
    if (!depth_) {
        depth_ = std::make_unique<DepthRenderer>();
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // PCF across cube face edges
    }
    // Every moments light's programs, on the first frame, whether or not its map renders now.
    for (const LightShadow& light : lights_) {
        if (light.settings.variant == Variant::None || mapLookupFor(light.settings).momentChannels() == 0) continue;
        if (!moments_) moments_ = std::make_unique<MomentsRenderer>();
        moments_->prepare(momentsKind(light));
    }
    for (const LightShadow& light : lights_)
        if (light.settings.variant == Variant::Volume && !volumes_) {
            volumes_ = std::make_unique<VolumeRenderer>(volumesOnGpu_, volumesZPass_);
            volumes_->prepareScene(frame.scene());
        }
    for (const LightShadow& light : lights_)
        if (light.settings.casterLod > 0.0 && !casterLods_) casterLods_ = std::make_unique<CasterLods>(frame.scene());
    levelDraws_.assign(lights_.size(), {});
    const PlanContext context = planContext(frame.scene(), frame.camera());
    const auto warn = [this](const LightShadow& light, const std::string& message) { warnOnce(light, message); };
    if (frame.clusteredLights()) {
        const engine::ResourceHandle atlas = atlas_.addPasses(frame, lights_, context, *depth_, closedMeshes_,
                                                              casterLods_.get(), levelDraws_, sceneGeneration_,
                                                              cacheMaps_, warn);
        cacheHits_ += atlas_.counts().cached;
        cacheMisses_ += atlas_.counts().rendered;
        for (const LightShadow& light : lights_) {
            for (const std::string& warning : light.frame.warnings) warnOnce(light, warning);
            frame.publishShadowView(light.view());
        }
        frame.setLightVisibility(atlas_.hook(frame, lights_, atlas));
        return;
    }
    std::vector<engine::ResourceHandle> maps;
    for (LightShadow& light : lights_) {
        if (light.slot >= engine::kMaxLights) break;  // the unrolled lit pass renders no more
        // Each shadowed light samples its map on unit kFirstPluginTextureUnit + slot.
        const bool shadowed =
            planLight(light, context, engine::kFirstPluginTextureUnit + light.slot, maxTextureUnits_);
        if (shadowed && light.frame.kind == MapKind::Screen) {
            const engine::ResourceHandle visibility =
                addVolumePass(light, frame, *volumes_, *depth_, sceneGeneration_, cacheMaps_);
            (light.frame.cacheHit ? cacheHits_ : cacheMisses_) += 1;
            light.frame.map = visibility;
            maps.push_back(visibility);
        } else if (shadowed) {
            light.ensureMap();
            light.ensureMoments();
            planUnseenShadows(light, context);
            decideCache(light, frame.scene(), sceneGeneration_, cacheMaps_);
            keepCachedMapsThatHoldTheNeededCasters(light);
            const MapShape shape = mapProjection(light.frame.kind)->shape(light);
            const int size = light.settings.resolution;
            const engine::TextureDesc desc{size, size, graphFormat(light.settings.depthFormat),
                                           shape.arrayLayers(),
                                           shape.target == MapShape::Target::Cube};
            engine::ResourceHandle map = frame.graph().importTexture(light.mapResource(), desc, light.map.id());
            engine::ResourceHandle moments;  // vsm, evsm: what the lit pass reads instead of the map
            if (light.moments.id())
                moments = frame.graph().importTexture(light.momentsResource(), light.momentsDesc(), light.moments.id());
            if (light.frame.cacheHit) {
                ++cacheHits_;  // the map is an input nobody writes this frame: no depth pass
            } else {
                ++cacheMisses_;
                addDepthPasses(light, frame, map, *depth_, closedMeshes_, casterLods_.get(),
                               levelDraws_[&light - lights_.data()]);  // moves map to its last version
                if (moments.valid()) addMomentsPasses(light, frame, map, moments, *moments_);
            }
            light.frame.map = map;  // the version the lit pass (and its comparison view) reads
            maps.push_back(map);
            if (moments.valid()) maps.push_back(moments);
        }
        for (const std::string& warning : light.frame.warnings) warnOnce(light, warning);
    }
    // Every light instance's view, shadowed or not (ShadowView.h): what the tools read.
    for (const LightShadow& light : lights_)
        if (light.slot < engine::kMaxLights) frame.publishShadowView(light.view());
    engine::LightVisibilityHook hook =
        hook_.build(frame, lights_, cacheMaps_, maxTextureUnits_,
                    [this](const LightShadow& light, const std::string& message) { warnOnce(light, message); });
    hook.reads = std::move(maps);
    frame.setLightVisibility(std::move(hook));
}

nlohmann::json ShadowMapPlugin::frameStats() const {
    nlohmann::json lights = nlohmann::json::array();
    for (const LightShadow& light : lights_) {
        nlohmann::json stats = light.stats();
        // caster_lod: the depth passes' draws per level (0: as loaded).
        if (light.settings.casterLod > 0.0) {
            const std::size_t index = &light - lights_.data();
            stats["lod_draws"] = index < levelDraws_.size() ? levelDraws_[index] : std::vector<std::uint64_t>{};
        }
        // JSON has no infinity: an infinite far plane (far_plane "infinite", reversed_z)
        // is reported as the string "infinite".
        if (stats.contains("far") && stats["far"].is_number() && std::isinf(stats["far"].get<double>()))
            stats["far"] = "infinite";
        if (light.settings.reversedZ) stats["reversed_z"] = true;
        lights.push_back(std::move(stats));
    }
    nlohmann::json out = {{"lights", lights}, {"cache_hits", cacheHits_}, {kCacheMapsKey, cacheMaps_},
                          {"cache_misses", cacheMisses_}};
    if (const nlohmann::json atlas = atlas_.stats(); !atlas.is_null()) out["atlas"] = atlas;
    if (casterLods_) out["caster_lod"] = {{"build_s", casterLods_->buildSeconds()}, {"meshes", casterLods_->stats()}};
    return out;
}

} // namespace shadowmap
