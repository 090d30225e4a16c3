#include "SavedShadow.h"

#include "engine/util/Error.h"

#include "shadowmap/ShadowSettings.h"

namespace tools {

nlohmann::json savedShadow(const nlohmann::json& configSettings, const nlohmann::json& loaded,
                           const nlohmann::json& current) {
    // The defaults a light without extras.shadow gets: built-in <- config (only the keys the
    // settings API knows: the config also holds plugin-wide keys such as cache_maps).
    nlohmann::json configured = nlohmann::json::object();
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys())
        if (configSettings.is_object() && configSettings.contains(key.name)) configured[key.name] = configSettings[key.name];
    const shadowmap::ShadowSettings defaults = shadowmap::parseSettings(configured, "engine config", "defaults");

    nlohmann::json shadow = nlohmann::json::object();
    if (!current.is_object()) return shadow;
    for (const auto& [key, value] : current.items()) {
        bool differs = true;
        try {
            shadowmap::ShadowSettings withKey = defaults;
            shadowmap::applySettings(withKey, {{key, value}}, "saved settings", "light");
            differs = !(withKey == defaults);
        } catch (const engine::InputError&) {
            // The plugin refused it when applied; keep it so the file shows what was typed.
        }
        if ((loaded.is_object() && loaded.contains(key)) || differs) shadow[key] = value;
    }
    return shadow;
}

} // namespace tools
