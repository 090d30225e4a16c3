#pragma once
// The shadow plugin: per light, a depth pass into a shadow map it owns, and the lit pass's
// visibility hook (texgen eye planes, hardware comparison, ambient-retaining modulate).
#include "plugin/DepthRenderer.h"
#include "plugin/HookGlsl.h"
#include "plugin/LightShadow.h"
#include "shadowmap/ShadowSettings.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Sampler.h"
#include "engine/plugin/RenderPlugin.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace shadowmap {

class ShadowMapPlugin final : public engine::RenderPlugin {
public:
    // cacheMaps: keep a light's map across frames while its inputs are unchanged, and give
    // the lit pass shade keys so it may reuse the lights' shade too.
    ShadowMapPlugin(const ShadowSettings& defaults, bool cacheMaps)
        : defaults_(defaults), cacheMaps_(cacheMaps) {}

    std::string name() const override { return kPluginName; }
    // Any key of extras.shadow (ShadowSettings.h), checked now: over the light's extras.
    bool setLightOption(const std::string& light, const std::string& key, const nlohmann::json& value) override;
    // The light's glTF extras.shadow.
    nlohmann::json sceneLightSettings(const engine::Scene& scene, int slot) const override;
    void prepareScene(const engine::Scene& scene) override;
    void reloadSettings(const engine::Scene& scene) override;
    void addPasses(engine::Frame& frame) override;
    nlohmann::json frameStats() const override;

private:
    bool planLight(LightShadow& light, const engine::Frame& frame, const ShadowBounds& bounds);
    // Adds the light's depth passes, one per map layer (the 2D map, each cube face, or each
    // cascade whose layer is not still right; woo: two per layer); the last one records
    // `key` once it has run (cascades: each records its layer's key).
    void addDepthPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map,
                        std::uint64_t key);
    // The passes rendering one layer of the map (-1: the 2D map) from P_light * L^-1; without
    // casters to draw, one pass that only clears it.
    void addLayerPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map, int layer,
                        const glm::dmat4& viewProjection, bool drawCasters, const DepthPassStyle& style,
                        std::uint64_t* keyTarget, std::uint64_t keyWhenDone);
    // Each cascade's key and whether its layer is still right (into light.frame); returns
    // the map's key, all layers' keys combined.
    std::uint64_t cascadeKeys(LightShadow& light, const engine::Scene& scene);
    void reportOpenCasters(LightShadow& light, const engine::Frame& frame);
    engine::LightVisibilityHook makeHook(const engine::Frame& frame);
    void warnOnce(const LightShadow& light, const std::string& message);
    // Resolves every light's settings (defaults, extras.shadow, command line) into lights_.
    void resolveLights(const engine::Scene& scene);
    const engine::gl::Sampler& rawDepthSampler();  // comparison off: reads a map's depth

    ShadowSettings defaults_;
    std::map<std::string, nlohmann::json> lightOptions_;  // light name -> {key: value}, command line
    std::vector<LightShadow> lights_;                  // one per lit-pass light slot
    std::vector<bool> closedMeshes_;                   // per mesh: closed, not double-sided
    std::unique_ptr<DepthRenderer> depth_;             // created with the first frame (needs GL)
    int maxTextureUnits_ = 16;                         // GL_MAX_TEXTURE_IMAGE_UNITS
    engine::gl::Sampler rawDepthSampler_;
    engine::gl::Buffer shadowBlock_;                   // ShadowBlock.h, refilled every frame
    HookGlsl hookGlsl_;                                // the hook's code per map layout
    std::set<std::string> warned_;                     // warnings already printed
    std::string scenePath_;                            // the scene's file, for messages
    bool cacheMaps_ = true;
    std::uint64_t sceneGeneration_ = 0;
    std::uint64_t cacheHits_ = 0, cacheMisses_ = 0;  // since the scene was prepared
};

} // namespace shadowmap
