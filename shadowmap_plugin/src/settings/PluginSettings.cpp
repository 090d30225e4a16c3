// The plugin's config settings (shadowmap/ShadowSettings.h): the per-light defaults and the
// plugin-wide keys, checked together so an unknown key's message lists every known one.
#include "shadowmap/ShadowSettings.h"

#include "engine/util/Error.h"
#include "engine/util/JsonRead.h"

namespace shadowmap {

namespace {

// The object the messages name, as the engine config nests it: plugins[...].settings.
constexpr char kObject[] = "settings";

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
    if (json.contains(kVolumeExtrusionKey)) {
        const std::string object = std::string(kObject) + "." + kVolumeExtrusionKey;
        const std::string where = engine::json::readString(json[kVolumeExtrusionKey], source, object);
        if (where != "cpu" && where != "gpu")
            engine::throwInputError(source, object, "unknown value \"" + where + "\" (known: cpu, gpu)");
        settings.volumesOnGpu = where == "gpu";
        lightDefaults.erase(kVolumeExtrusionKey);
    }
    if (json.contains(kVolumeCountingKey)) {
        const std::string object = std::string(kObject) + "." + kVolumeCountingKey;
        const std::string how = engine::json::readString(json[kVolumeCountingKey], source, object);
        if (how != "auto" && how != "z-fail")
            engine::throwInputError(source, object, "unknown value \"" + how + "\" (known: auto, z-fail)");
        settings.volumesZPass = how == "auto";
        lightDefaults.erase(kVolumeCountingKey);
    }
    applySettings(settings.lightDefaults, lightDefaults, source, kObject);
    return settings;
}

} // namespace shadowmap
