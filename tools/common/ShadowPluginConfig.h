#pragma once
// The shadow plugin's entry in an engine config, as the measuring tools need it
// (shadowmap-bench, shadowmap-tune, engine-view): its settings (the defaults a light's
// extras.shadow overrides) and map caching turned off for timing.
#include "engine/config/EngineConfig.h"
#include "shadowmap/ShadowSettings.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tools {

inline constexpr const char* kShadowPlugin = shadowmap::kPluginName;

// The shadow plugin's settings object in the config (empty when it loads none).
nlohmann::json shadowPluginSettings(const engine::EngineConfig& config);

// Cached maps render once and later frames would time nothing: every frame must re-render.
// An InputError naming the config when it loads no shadow plugin (nothing to measure).
void disableShadowMapCaching(engine::EngineConfig& config, const std::string& configPath);

} // namespace tools
