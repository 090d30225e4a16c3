#pragma once
// The shadow plugin: per light, depth passes into a shadow map it owns, and the lit pass's
// visibility hook (texgen eye planes, hardware comparison, ambient-retaining modulate). The
// glue between the engine and the techniques (technique/Techniques.h): it resolves the
// lights' settings, asks the planner what each light needs this frame, keeps the maps, and
// lets each light's techniques declare their passes and lookups.
#include "plugin/CasterLods.h"
#include "plugin/AtlasMaps.h"
#include "plugin/DepthRenderer.h"
#include "plugin/LightResolver.h"
#include "plugin/LightShadow.h"
#include "plugin/MomentsRenderer.h"
#include "plugin/ShadowHook.h"
#include "plugin/VolumeRenderer.h"
#include "shadowmap/ShadowSettings.h"

#include "engine/plugin/RenderPlugin.h"

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace shadowmap {

class ShadowMapPlugin final : public engine::RenderPlugin {
public:
    // cacheMaps: keep a light's map across frames while its inputs are unchanged, and give
    // the lit pass shade keys so it may reuse the lights' shade too. volumesOnGpu: where
    // variant volume's volumes are made (shadowmap/ShadowSettings.h volume_extrusion).
    explicit ShadowMapPlugin(const PluginSettings& settings)
        : defaults_(settings.lightDefaults),
          cacheMaps_(settings.cacheMaps),
          volumesOnGpu_(settings.volumesOnGpu),
          volumesZPass_(settings.volumesZPass) {}

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
    void resolve(const engine::Scene& scene);
    void warnOnce(const LightState& light, const std::string& message);

    ShadowSettings defaults_;
    LightOptions lightOptions_;                 // from the command line
    std::vector<LightShadow> lights_;           // one per lit-pass light slot
    std::vector<bool> closedMeshes_;            // per mesh: closed, not double-sided
    std::unique_ptr<DepthRenderer> depth_;      // created with the first frame (needs GL)
    // caster_lod's levels: made with the first frame of a scene in which a light asks for them.
    std::unique_ptr<CasterLods> casterLods_;
    std::vector<std::vector<std::uint64_t>> levelDraws_;  // per light: this frame's draws per level
    std::unique_ptr<MomentsRenderer> moments_;  // created with the first frame with a vsm or evsm light
    std::unique_ptr<VolumeRenderer> volumes_;  // created with the first frame with a volume light, per scene
    int maxTextureUnits_ = 16;                  // GL_MAX_TEXTURE_IMAGE_UNITS
    ShadowHook hook_;
    AtlasMaps atlas_;  // the maps of frames the clustered lit pass shades
    std::set<std::string> warned_;              // warnings already printed
    std::string scenePath_;                     // the scene's file, for messages
    bool cacheMaps_ = true;
    bool volumesOnGpu_ = false;
    bool volumesZPass_ = true;
    std::uint64_t sceneGeneration_ = 0;
    std::uint64_t cacheHits_ = 0, cacheMisses_ = 0;  // since the scene was prepared
};

} // namespace shadowmap
