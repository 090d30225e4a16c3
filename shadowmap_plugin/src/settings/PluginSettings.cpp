// The plugin's config settings (shadowmap/ShadowSettings.h): the per-light defaults and the
// plugin-wide keys, checked together so an unknown key's message lists every known one.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Error.h"
#include "engine/util/JsonRead.h"

#include <algorithm>
#include <optional>

namespace shadowmap {

namespace {

// The object the messages name, as the engine config nests it: plugins[...].settings.
constexpr char kObject[] = "settings";

// A plugin-wide key whose value is one of `known` words: the word, taken out of the light
// defaults, or nullopt when the key is absent.
std::optional<std::string> readChoice(const nlohmann::json& json, const char* key,
                                      const std::vector<std::string>& known, const std::string& source,
                                      nlohmann::json& lightDefaults) {
    if (!json.contains(key)) return std::nullopt;
    const std::string object = std::string(kObject) + "." + key;
    const std::string word = engine::json::readString(json[key], source, object);
    if (std::find(known.begin(), known.end(), word) == known.end()) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        engine::throwInputError(source, object, "unknown value \"" + word + "\" (known: " + list + ")");
    }
    lightDefaults.erase(key);
    return word;
}

} // namespace

std::vector<std::string> pluginSettingKeys() {
    std::vector<std::string> keys;
    for (const SettingKey& key : settingKeys()) keys.push_back(key.name);
    keys.push_back(kCacheMapsKey);
    keys.push_back(kVolumeExtrusionKey);
    keys.push_back(kVolumeCountingKey);
    return keys;
}

PluginSettings parsePluginSettings(const nlohmann::json& json, const std::string& source) {
    static const std::vector<std::string> known = pluginSettingKeys();
    engine::json::requireKnownKeys(json, known, source, kObject);
    PluginSettings settings;
    nlohmann::json lightDefaults = json;
    if (json.contains(kCacheMapsKey)) {
        settings.cacheMaps =
            engine::json::readBool(json[kCacheMapsKey], source, std::string(kObject) + "." + kCacheMapsKey);
        lightDefaults.erase(kCacheMapsKey);
    }
    if (const auto where = readChoice(json, kVolumeExtrusionKey, {"cpu", "gpu"}, source, lightDefaults))
        settings.volumesOnGpu = *where == "gpu";
    if (const auto how = readChoice(json, kVolumeCountingKey, {"auto", "z-fail"}, source, lightDefaults))
        settings.volumesZPass = *how == "auto";
    applySettings(settings.lightDefaults, lightDefaults, source, kObject);
    return settings;
}

} // namespace shadowmap
