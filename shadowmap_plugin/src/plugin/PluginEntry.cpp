// The plugin's one exported entry point: registers a ShadowMapPlugin whose defaults are the
// built-in ones overridden by the "settings" of the engine config (unknown keys refused).
#include "plugin/ShadowMapPlugin.h"

#include <engine_plugin/PluginAbi.h>

namespace {

void registerShadowMap(engine::PluginRegistry* registry, const char* settingsJson) {
    shadowmap::ShadowSettings defaults;
    shadowmap::applySettings(defaults, nlohmann::json::parse(settingsJson), "", "settings");
    registry->addRenderPlugin(std::make_unique<shadowmap::ShadowMapPlugin>(defaults));
}

} // namespace

ENGINE_DECLARE_PLUGIN("shadowmap", &registerShadowMap)
