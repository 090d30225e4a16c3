#pragma once
// --set PLUGIN.KEY=VALUE, shared by the tools that load plugins from an engine config
// (engine-render, shadowmap-bench, shadowmap-stress): one override of one plugin setting.
// The plugin is named by its library in the config; the value is JSON, a bare word counting
// as a string (--set shadowmap_plugin.variant=woo), and the plugin checks it like any
// config setting.
#include "engine/config/EngineConfig.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tools {

struct SettingOverride {
    std::string plugin;   // the library's name in the config: "shadowmap_plugin"
    std::string key;      // the setting: "resolution"
    nlohmann::json value;
    std::string text;     // as given, for messages
};

// Throws std::invalid_argument naming the flag when the text is not PLUGIN.KEY=VALUE with
// every part non-empty.
SettingOverride parseSettingOverride(const std::string& flag, const std::string& text);

// parseSettingOverride, appended to `overrides`. The same PLUGIN.KEY twice is an error naming
// both values: which one was meant is not ours to guess.
void addSettingOverride(std::vector<SettingOverride>& overrides, const std::string& flag, const std::string& text);

// An option's value as JSON, a bare word counting as a string: 512, [1,2], true, woo.
nlohmann::json parseJsonOrWord(const std::string& text);

// OWNER.KEY=VALUE, the shape of --set (owner: a plugin) and --light-set (owner: a light).
// The owner ends at the first dot, or at the last one when `ownerMayHoldDots` (light names
// such as "Light.001"; no key holds a dot). Throws std::invalid_argument naming the flag and
// `shape` (e.g. "PLUGIN.KEY") when a part is missing or empty.
struct KeyAssignment {
    std::string owner, key;
    nlohmann::json value;
};
KeyAssignment parseKeyAssignment(const std::string& flag, const std::string& text, const std::string& shape,
                                 bool ownerMayHoldDots);

// Applies each override to the config's plugin of that name. Throws engine::InputError when
// the config loads no such plugin (naming the config's source and the plugins it loads).
void applySettingOverrides(engine::EngineConfig& config, const std::vector<SettingOverride>& overrides);

} // namespace tools
