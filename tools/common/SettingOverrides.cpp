#include "SettingOverrides.h"

#include "engine/util/Error.h"

#include <stdexcept>

namespace tools {

KeyAssignment parseKeyAssignment(const std::string& flag, const std::string& text, const std::string& shape,
                                 bool ownerMayHoldDots) {
    const auto refuse = [&](const std::string& why) {
        return std::invalid_argument(flag + ": \"" + text + "\" must be " + shape + "=VALUE (" + why + ")");
    };
    const auto equals = text.find('=');
    if (equals == std::string::npos) throw refuse("no '='");
    const std::string target = text.substr(0, equals), value = text.substr(equals + 1);
    if (value.empty()) throw refuse("no value");
    const auto dot = ownerMayHoldDots ? target.rfind('.') : target.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == target.size())
        throw refuse("\"" + target + "\" is not " + shape);
    return {target.substr(0, dot), target.substr(dot + 1), parseJsonOrWord(value)};
}

SettingOverride parseSettingOverride(const std::string& flag, const std::string& text) {
    KeyAssignment assignment = parseKeyAssignment(flag, text, "PLUGIN.KEY", false);
    return {std::move(assignment.owner), std::move(assignment.key), std::move(assignment.value), text};
}

void addSettingOverride(std::vector<SettingOverride>& overrides, const std::string& flag, const std::string& text) {
    SettingOverride setting = parseSettingOverride(flag, text);
    for (const SettingOverride& earlier : overrides)
        if (earlier.plugin == setting.plugin && earlier.key == setting.key)
            throw std::invalid_argument(flag + " " + setting.plugin + "." + setting.key + " is given twice: " +
                                        earlier.value.dump() + " and " + setting.value.dump());
    overrides.push_back(std::move(setting));
}

nlohmann::json parseJsonOrWord(const std::string& text) {
    nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    if (parsed.is_discarded()) return text;  // a bare word is a string
    return parsed;
}

void applySettingOverrides(engine::EngineConfig& config, const std::vector<SettingOverride>& overrides) {
    for (const SettingOverride& setting : overrides) {
        bool found = false;
        for (engine::PluginConfig& plugin : config.plugins)
            if (plugin.library == setting.plugin) {
                plugin.settings[setting.key] = setting.value;
                found = true;
            }
        if (!found) {
            std::string loaded;
            for (const engine::PluginConfig& plugin : config.plugins)
                loaded += (loaded.empty() ? "" : ", ") + plugin.library;
            throw engine::InputError("--set " + setting.text + ": the config " + config.sourcePath.string() +
                                     " loads no plugin \"" + setting.plugin + "\" (it loads: " +
                                     (loaded.empty() ? "none" : loaded) + ")");
        }
    }
}

} // namespace tools
