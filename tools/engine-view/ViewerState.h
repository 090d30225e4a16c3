#pragma once
// What the author is looking at and what they changed: the selected light, the debug view,
// and each light's live shadow settings, kept where the plugin reads them (the glTF light's
// extras.shadow in the Scene), so Renderer::reloadSettings applies them next frame and the
// plugin's cache re-renders only the lights whose settings changed.
#include "engine/render/Renderer.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace engine_view {

// In the order D cycles them (the penumbra right after the shadow term it is drawn from).
enum class DebugView {
    Shaded, LightView, DepthMap, ProjectedDepth, Comparison, ShadowTerm, Penumbra, AcneLeak, Cascades, TexelDensity
};
constexpr int kDebugViewCount = 10;
// "shaded", "light", "depth", "projected", "comparison", "shadow", "penumbra", "truth", "cascades",
// "density"
const char* viewName(DebugView view);
std::optional<DebugView> parseView(const std::string& name);
// Every view's name, in order, comma-separated (for error messages).
std::string viewNames();

// A light's size as the size keys step it: the setting its type is sized by (light_radius
// for spot and point lights, angular_diameter for directional ones), on the ladder
// smallest * kLightSizeStep^k (four significant digits). 0 (a point light) and the type's
// smallest size are one step apart, so the keys reach 0 and leave it.
constexpr double kLightSizeStep = 1.5;
const char* lightSizeKey(engine::Light::Type type);
double smallestLightSize(engine::Light::Type type);
// `size` one step larger (grow) or smaller, as the keys step it.
double stepLightSize(double size, engine::Light::Type type, bool grow);

struct ViewedLight {
    std::string name;  // as the shadow plugin names it: the light's name, else its node's
    int slot = -1;     // index into scene.lightInstances (the lit pass's slot)
    int light = -1;    // index into scene.lights (the glTF light object holding extras)
    engine::Light::Type type = engine::Light::Type::Point;
};

class ViewerState {
public:
    // `pluginDefaults`: the shadow plugin's settings from the engine config (the defaults a
    // light's extras.shadow overrides).
    ViewerState(engine::Scene& scene, nlohmann::json pluginDefaults);

    const std::vector<ViewedLight>& lights() const { return lights_; }
    int selected() const { return selected_; }  // index into lights(), -1 when none
    void selectNext();
    bool select(const std::string& name);
    int find(const std::string& name) const;  // index into lights(), -1 when absent

    DebugView view() const { return view_; }
    void setView(DebugView view) { view_ = view; }
    void nextView() { view_ = static_cast<DebugView>((static_cast<int>(view_) + 1) % kDebugViewCount); }
    // M: into the texel-density view and back to the view it left, so the heat map can be
    // held against any other view with one key.
    void toggleTexelDensity();

    // The keys' edits, on the selected light (nothing when there is none). The cycles are
    // the shadow plugin's allowed values (shadowmap::settingKeys()), in its order:
    void cycleVariant();     // standard -> woo -> backface -> none
    void cycleResolution();  // the resolution's steps: 512 -> 1024 -> 2048 -> 4096
    void cycleDepthFormat(); // d16 -> d24 -> d32f
    void toggleFilter();     // the next filter the light accepts (pcss: with a size)
    void cycleCascades();    // auto -> 1 -> 2 -> 3 -> 4 (directional lights; others ignore it)
    void toggleStable();     // stable cascades on <-> off
    void addOffsetUnits(double delta);  // polygon offset units, kept >= 0
    void addDimming(double delta);      // kept in [0, 1], rounded to 0.01
    // The light's size one step larger or smaller (stepLightSize). A step to 0 under pcss
    // also sets the filter to pcf (pcss needs a size): returns that note for the overlay,
    // else "".
    std::string growLightSize() { return changeLightSize(true); }
    std::string shrinkLightSize() { return changeLightSize(false); }
    // Any key of extras.shadow (the plugin checks it when applied).
    void set(int index, const std::string& key, const nlohmann::json& value);

    // Applies pending edits through renderer.reloadSettings(). A setting the plugin refuses
    // (InputError) is rolled back, the last good settings are reloaded, and the error rethrown.
    void apply(engine::Renderer& renderer);

    // The last frame's shadow views (what the plugin really used).
    void setFrameViews(std::vector<engine::ShadowView> views) { views_ = std::move(views); }
    const engine::ShadowView* frameView(int index) const;  // null when no plugin published one

    // The light's effective settings: the plugin's built-in defaults (printSettings of
    // shadowmap::ShadowSettings{}) <- config <- extras.shadow, with the polygon offset the
    // plugin reported when it is not explicit.
    nlohmann::json effective(int index) const;
    // What --save-settings writes as the light's extras.shadow (tools/common/SavedShadow.h,
    // shared with shadowmap-tune): the keys the loaded file already had, as they are now, and
    // of the keys set here (keys, script, --light-set) only those that differ from the defaults.
    nlohmann::json savedShadow(int index) const;

private:
    nlohmann::json& shadowOf(int index);  // scene.lights[...].extras["shadow"], created on demand
    std::string changeLightSize(bool grow);

    engine::Scene& scene_;
    nlohmann::json defaults_;
    std::vector<ViewedLight> lights_;
    std::vector<nlohmann::json> applied_;  // per scene.lights entry: extras last applied
    std::vector<nlohmann::json> loaded_;   // per scene.lights entry: extras.shadow as loaded
    bool dirty_ = false;
    int selected_ = -1;
    DebugView view_ = DebugView::Shaded;
    DebugView beforeTexelDensity_ = DebugView::Shaded;  // where M goes back to
    std::vector<engine::ShadowView> views_;
};

} // namespace engine_view
