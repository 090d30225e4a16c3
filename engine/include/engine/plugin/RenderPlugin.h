#pragma once
// What a plugin registers: RenderPlugin objects that add passes to every frame's graph and,
// optionally, the lit pass's per-light visibility term (the shadow plugin's hook).
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace engine {

class Frame;
struct Scene;

class RenderPlugin {
public:
    virtual ~RenderPlugin() = default;
    virtual std::string name() const = 0;

    // A per-light setting from the command line (engine-render --light-set NAME.KEY=JSON;
    // --light NAME=VARIANT is the key "variant"), given before prepareScene, at most once per
    // light and key. It wins over every other source of that light's setting. `light` is the
    // instance's name (engine/scene/SceneNames.h). Returns false when this plugin has no
    // per-light settings; throws InputError naming the light, the key and the reason when it
    // has no such key or the value is bad.
    virtual bool setLightOption(const std::string& light, const std::string& key, const nlohmann::json& value) {
        return false;
    }
    // The per-light settings the scene gives light instance `slot` itself (the shadow plugin:
    // its glTF extras.shadow), as a JSON object key -> value. They win over the plugin's
    // config settings, so a tool can say when a config override it applied does nothing there.
    virtual nlohmann::json sceneLightSettings(const Scene& scene, int slot) const {
        return nlohmann::json::object();
    }
    // The scene was loaded (or replaced). Validate per-light settings here and throw
    // InputError naming the light for bad ones.
    virtual void prepareScene(const Scene& scene) {}
    // Only settings changed (lights' extras, options): same geometry, same nodes. A plugin
    // may keep what the change does not touch (the shadow plugin keeps unchanged maps).
    virtual void reloadSettings(const Scene& scene) { prepareScene(scene); }
    // Adds this frame's passes (setup runs now, execute later) and hooks into the frame.
    virtual void addPasses(Frame& frame) = 0;
    // Plugin-specific figures for --stats (after the frame executed).
    virtual nlohmann::json frameStats() const { return nlohmann::json::object(); }
};

// Handed to a plugin's registerPlugin(); owned by the engine's PluginHost.
class PluginRegistry {
public:
    void addRenderPlugin(std::unique_ptr<RenderPlugin> plugin) {
        plugins_.push_back(std::move(plugin));
    }
    std::vector<std::unique_ptr<RenderPlugin>>& renderPlugins() { return plugins_; }

private:
    std::vector<std::unique_ptr<RenderPlugin>> plugins_;
};

} // namespace engine
