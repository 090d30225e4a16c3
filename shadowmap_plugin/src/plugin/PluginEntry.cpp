// The plugin's one exported entry point: registers a ShadowMapPlugin whose defaults are the
// built-in ones overridden by the "settings" of the engine config (unknown keys refused).
#include "plugin/ShadowMapPlugin.h"

#include "engine/util/JsonRead.h"

#include <engine_plugin/PluginAbi.h>

namespace {

// Plugin-wide keys besides the per-light defaults of shadowmap/ShadowSettings.h:
//   "cache_maps": true (default) keeps a light's map across frames while nothing it
//   depends on changed, and lets the lit pass reuse its shade; false re-renders every map
//   and recomputes every shade every frame (for timing the passes).
void registerShadowMap(engine::PluginRegistry* registry, const char* settingsJson) {
    nlohmann::json settings = nlohmann::json::parse(settingsJson);
    bool cacheMaps = true;
    if (settings.contains("cache_maps")) {
        cacheMaps = engine::json::readBool(settings["cache_maps"], "", "settings.cache_maps");
        settings.erase("cache_maps");
    }
    shadowmap::ShadowSettings defaults;
    shadowmap::applySettings(defaults, settings, "", "settings");
    registry->addRenderPlugin(std::make_unique<shadowmap::ShadowMapPlugin>(defaults, cacheMaps));
}

} // namespace

ENGINE_DECLARE_PLUGIN(shadowmap::kPluginName, &registerShadowMap)
