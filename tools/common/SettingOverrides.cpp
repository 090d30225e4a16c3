#include "SettingOverrides.h"

#include "engine/util/Error.h"

#include <stdexcept>

namespace tools {

SettingOverride parseSettingOverride(const std::string& flag, const std::string& text) {
    const auto refuse = [&](const std::string& why) {
        return std::invalid_argument(flag + ": \"" + text + "\" must be PLUGIN.KEY=VALUE (" + why + ")");
    };
    const auto equals = text.find('=');
    if (equals == std::string::npos) throw refuse("no '='");
    const std::string target = text.substr(0, equals), value = text.substr(equals + 1);
    if (value.empty()) throw refuse("no value");
    const auto dot = target.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == target.size())
        throw refuse("\"" + target + "\" is not PLUGIN.KEY");
    nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
    if (parsed.is_discarded()) parsed = value;  // a bare word is a string
    return {target.substr(0, dot), target.substr(dot + 1), std::move(parsed), text};
}

void applySettingOverrides(engine::EngineConfig& config, const std::vector<SettingOverride>& overrides) {
    for (const SettingOverride& setting : overrides) {
        bool found = false;
        for (engine::PluginConfig& plugin : config.plugins)
            if (plugin.library == setting.plugin) {
                plugin.settings[setting.key] = setting.value;
                found = true;
            }
        if (!found)
            throw engine::InputError("--set " + setting.text + ": the config " + config.sourcePath.string() +
                                     " loads no plugin \"" + setting.plugin + "\"");
    }
}

} // namespace tools
