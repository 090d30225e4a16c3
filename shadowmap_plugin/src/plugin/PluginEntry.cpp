// The plugin's one exported entry point: registers a ShadowMapPlugin whose defaults are the
// built-in ones overridden by the "settings" of the engine config (unknown keys refused;
// the keys, per-light and plugin-wide, are the settings API's: shadowmap/ShadowSettings.h).
#include "plugin/ShadowMapPlugin.h"

#include <engine_plugin/PluginAbi.h>

namespace {

void registerShadowMap(engine::PluginRegistry* registry, const char* settingsJson) {
    // No source: the plugin host prefixes the config file and the plugin's name.
    const shadowmap::PluginSettings settings = shadowmap::parsePluginSettings(nlohmann::json::parse(settingsJson), "");
    registry->addRenderPlugin(std::make_unique<shadowmap::ShadowMapPlugin>(settings));
}

} // namespace

ENGINE_DECLARE_PLUGIN(shadowmap::kPluginName, &registerShadowMap)
