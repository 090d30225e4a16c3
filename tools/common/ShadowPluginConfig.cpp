#include "ShadowPluginConfig.h"

#include "engine/util/Error.h"

namespace tools {

nlohmann::json shadowPluginSettings(const engine::EngineConfig& config) {
    for (const engine::PluginConfig& plugin : config.plugins)
        if (plugin.library == kShadowPlugin) return plugin.settings;
    return nlohmann::json::object();
}

void disableShadowMapCaching(engine::EngineConfig& config, const std::string& configPath) {
    for (engine::PluginConfig& plugin : config.plugins)
        if (plugin.library == kShadowPlugin) {
            plugin.settings[shadowmap::kCacheMapsKey] = false;
            return;
        }
    engine::throwInputError(configPath, "plugins", "loads no " + std::string(kShadowPlugin) + ": nothing to measure");
}

} // namespace tools
