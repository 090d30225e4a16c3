#include "LightOverrides.h"

#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

namespace tools {

namespace {

// How the light is named in a suggested option: its name, unless that is no word a shell
// keeps whole or the name is the "light N" of an unnamed light, then its number.
std::string commandLineName(const engine::Scene& scene, int slot) {
    const std::string name = engine::lightInstanceName(scene, slot);
    const bool plainWord = !name.empty() && std::none_of(name.begin(), name.end(), [](char c) {
        return c == ' ' || c == '\'' || c == '"' || c == '\\' || c == '$' || c == '`';
    });
    return plainWord && engine::findLightInstanceByNameOrNumber(scene, name) >= 0 ? name : std::to_string(slot + 1);
}

constexpr const char* kIntensityKey = "intensity";
constexpr const char* kColorKey = "color";

// Finite as the lit pass holds it: a float.
bool finiteNonNegative(const nlohmann::json& value) {
    return value.is_number() && value.get<double>() >= 0.0 &&
           value.get<double>() <= static_cast<double>(std::numeric_limits<float>::max());
}

// Why `value` is no value of the light property `key`, or "" when it is one.
std::string lightPropertyProblem(const std::string& key, const nlohmann::json& value) {
    if (key == kIntensityKey)
        return finiteNonNegative(value) ? "" : "must be a finite number >= 0 (0: the light emits nothing)";
    const bool rgb = value.is_array() && value.size() == 3 && std::all_of(value.begin(), value.end(), finiteNonNegative);
    return rgb ? "" : "must be [r, g, b], three finite numbers >= 0 (linear)";
}

} // namespace

bool isLightPropertyKey(const std::string& key) { return key == kIntensityKey || key == kColorKey; }

LightOverride parseLightSetting(const std::string& flag, const std::string& text) {
    KeyAssignment assignment = parseKeyAssignment(flag, text, "NAME.KEY", true);
    // A light property's value is checked here, before any file is read: the plugins that
    // check the shadow keys never see it.
    if (isLightPropertyKey(assignment.key))
        if (const std::string problem = lightPropertyProblem(assignment.key, assignment.value); !problem.empty())
            throw std::invalid_argument(flag + " " + text + ": light \"" + assignment.owner + "\"." + assignment.key +
                                        " " + problem + ", got " + assignment.value.dump());
    return {std::move(assignment.owner), std::move(assignment.key), std::move(assignment.value), flag + " " + text};
}

LightOverride parseLightVariant(const std::string& flag, const std::string& text) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        throw std::invalid_argument(flag + ": \"" + text + "\" must be NAME=VARIANT");
    // The variant is a word, never JSON: --light sun=none is "none", not null.
    return {text.substr(0, equals), "variant", text.substr(equals + 1), flag + " " + text};
}

std::vector<LightOverride> resolveLightOverrides(const std::vector<LightOverride>& overrides,
                                                 const std::function<std::string(const std::string&)>& resolve) {
    std::vector<LightOverride> resolved;
    for (const LightOverride& option : overrides) {
        LightOverride named = option;
        named.light = resolve(option.light);
        for (const LightOverride& earlier : resolved)
            if (earlier.light == named.light && earlier.key == named.key)
                throw engine::InputError(option.text + ": light \"" + named.light + "\"." + named.key +
                                         " is already set by " + earlier.text + " (" + earlier.value.dump() +
                                         " and " + named.value.dump() + "): give each light and key once");
        resolved.push_back(std::move(named));
    }
    return resolved;
}

std::vector<LightOverride> applyLightProperties(engine::Scene& scene, const std::vector<LightOverride>& resolved,
                                                std::vector<std::string>& warnings) {
    std::vector<LightOverride> rest;
    for (const LightOverride& option : resolved) {
        if (!isLightPropertyKey(option.key)) {
            rest.push_back(option);
            continue;
        }
        const int instances = static_cast<int>(scene.lightInstances.size());
        std::set<int> lights;  // the glTF lights the named instances place
        for (int slot = 0; slot < instances; ++slot)
            if (engine::lightInstanceName(scene, slot) == option.light) lights.insert(scene.lightInstances[slot].light);
        for (const int index : lights) {
            engine::Light& light = scene.lights[index];
            if (option.key == kIntensityKey) light.intensity = option.value.get<float>();
            else light.color = {option.value[0].get<float>(), option.value[1].get<float>(), option.value[2].get<float>()};
        }
        for (int slot = 0; slot < instances; ++slot) {
            const std::string other = engine::lightInstanceName(scene, slot);
            if (other != option.light && lights.count(scene.lightInstances[slot].light))
                warnings.push_back(option.text + " also sets light \"" + other + "\": it places the same glTF light (" +
                                   option.key + " is the light's, shared by every node that places it)");
        }
    }
    return rest;
}

void applyLightOverrides(const std::vector<LightOverride>& resolved, const std::vector<engine::RenderPlugin*>& plugins,
                         const std::string& configPath) {
    for (const LightOverride& option : resolved) {
        bool taken = false;
        for (engine::RenderPlugin* plugin : plugins) {
            try {
                taken = plugin->setLightOption(option.light, option.key, option.value) || taken;
            } catch (const engine::InputError& error) {
                throw engine::InputError(option.text + ": " + error.what());
            }
        }
        if (!taken)
            throw engine::InputError(option.text + ": no loaded plugin takes per-light settings (config " +
                                     configPath + " loads " + std::to_string(plugins.size()) + " plugins)");
    }
}

std::vector<std::string> shadowedSettingWarnings(const std::vector<SettingOverride>& settings,
                                                 const std::vector<LightOverride>& resolved,
                                                 const engine::PluginHost& host, const engine::Scene& scene) {
    std::vector<std::string> warnings;
    std::set<std::string> said;  // instances sharing a name share their warning
    for (const SettingOverride& setting : settings)
        for (const engine::RenderPlugin* plugin : host.renderPlugins(setting.plugin))
            for (int slot = 0; slot < static_cast<int>(scene.lightInstances.size()); ++slot) {
                const nlohmann::json own = plugin->sceneLightSettings(scene, slot);
                if (!own.is_object() || !own.contains(setting.key)) continue;
                const std::string light = engine::lightInstanceName(scene, slot);
                const bool overridden = std::any_of(resolved.begin(), resolved.end(), [&](const LightOverride& option) {
                    return option.light == light && option.key == setting.key;
                });
                if (overridden) continue;
                const std::string warning =
                    "--set " + setting.text + " does nothing for light \"" + light + "\": its glTF extras set " +
                    setting.key + " to " + own[setting.key].dump() +
                    ", which wins (defaults < engine config and --set < the light's glTF extras < --light-set); "
                    "to override it for this light: --light-set " + commandLineName(scene, slot) + "." +
                    setting.key + "=" + setting.text.substr(setting.text.find('=') + 1);
                if (said.insert(warning).second) warnings.push_back(warning);
            }
    return warnings;
}

} // namespace tools
