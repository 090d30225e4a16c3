#pragma once
// The shadow plugin: per light, a depth pass into a shadow map it owns, and the lit pass's
// visibility hook (texgen eye planes, hardware comparison, ambient-retaining modulate).
#include "plugin/DepthRenderer.h"
#include "plugin/LightShadow.h"
#include "plugin/ShadowSettings.h"

#include "engine/plugin/RenderPlugin.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace shadowmap {

class ShadowMapPlugin final : public engine::RenderPlugin {
public:
    explicit ShadowMapPlugin(const ShadowSettings& defaults) : defaults_(defaults) {}

    std::string name() const override { return "shadowmap"; }
    bool setLightOption(const std::string& light, const std::string& value) override;
    void prepareScene(const engine::Scene& scene) override;
    void addPasses(engine::Frame& frame) override;
    nlohmann::json frameStats() const override;

    // At most this many shadowed lights of each map kind per frame (texture units).
    static constexpr int kMax2DMaps = 8;
    static constexpr int kMaxCubeMaps = 4;

private:
    bool planLight(LightShadow& light, const engine::Frame& frame, const ShadowBounds& bounds,
                   int& used2D, int& usedCube);
    void addDepthPasses(LightShadow& light, engine::Frame& frame, engine::ResourceHandle map);
    // Renders the light's views (one 2D view or six cube faces) into `target` with `style`.
    void renderMap(LightShadow& light, const engine::Frame& frame, engine::PassContext& context,
                   unsigned target, bool targetIsArray, const DepthPassStyle& style);
    void reportOpenCasters(LightShadow& light, const engine::Frame& frame);
    engine::LightVisibilityHook makeHook(const engine::Frame& frame);
    void warnOnce(const LightShadow& light, const std::string& message);

    ShadowSettings defaults_;
    std::map<std::string, Variant> variantOverrides_;  // --light NAME=VARIANT
    std::vector<LightShadow> lights_;                  // one per lit-pass light slot
    std::vector<bool> closedMeshes_;                   // per mesh: closed, not double-sided
    std::unique_ptr<DepthRenderer> depth_;             // created with the first frame (needs GL)
    engine::gl::Texture unused2D_, unusedCube_;        // bound to sampler slots no light uses
    std::set<std::string> warned_;
};

} // namespace shadowmap
