#pragma once
// Per-light settings from the command line (engine-render --light-set NAME.KEY=JSON and its
// shorthand --light NAME=VARIANT): parsed, resolved to the scene's light instances, handed
// to the plugins, and the warning for a --set that a light's own settings make do nothing.
// Two keys are the light's own, not its shadow's (isLightPropertyKey): intensity and color
// go to the scene's engine::Light, which the lit pass reads, and no plugin sees them.
//
// Where a light's setting comes from, most specific last (docs/settings.md, "Precedence"):
// built-in defaults < the engine config's plugin settings (--set edits them) <
// the light's glTF extras < these per-light options.
#include "SettingOverrides.h"

#include "engine/plugin/PluginHost.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tools {

struct LightOverride {
    std::string light;     // as typed (a name or a number from --list); once resolved, the instance's name
    std::string key;       // "resolution"
    nlohmann::json value;  // JSON, a bare word counting as a string
    std::string text;      // the option as given, for messages: "--light sun=woo"
};

// --light-set NAME.KEY=JSON. The last '.' before the '=' splits (Blender names lights
// "Light.001"; no key holds a dot). Throws std::invalid_argument naming the flag; for a
// light property (below) also when its value is not one the property takes, naming the
// light, the key and the value.
LightOverride parseLightSetting(const std::string& flag, const std::string& text);

// The keys that are properties of the light itself (KHR_lights_punctual), not of its shadow:
//   intensity  a finite number >= 0, replacing the file's (lux for a directional light,
//              candela for the others; 0: the light emits nothing);
//   color      [r, g, b], linear, each finite and >= 0.
bool isLightPropertyKey(const std::string& key);

// Sets each override of a light property on `scene`'s engine::Light of every instance named
// option.light, and returns the other overrides, for the plugins (applyLightOverrides). A
// glTF light that an instance of another name places too changes for that instance as well
// (the property belongs to the light, not to the node): one warning per such instance.
std::vector<LightOverride> applyLightProperties(engine::Scene& scene, const std::vector<LightOverride>& resolved,
                                                std::vector<std::string>& warnings);
// --light NAME=VARIANT, which is --light-set NAME.variant=VARIANT.
LightOverride parseLightVariant(const std::string& flag, const std::string& text);

// Each override with its light replaced by resolve(typed word) (the instance's name; resolve
// throws for a light the scene lacks). The same light and key twice, however typed ("sun"
// and "2"), is an engine::InputError naming both options.
std::vector<LightOverride> resolveLightOverrides(const std::vector<LightOverride>& overrides,
                                                 const std::function<std::string(const std::string&)>& resolve);

// Hands each resolved override to every plugin (RenderPlugin::setLightOption). A plugin's
// refusal is rethrown prefixed with the option; an option no plugin takes is an InputError
// naming the config.
void applyLightOverrides(const std::vector<LightOverride>& resolved, const std::vector<engine::RenderPlugin*>& plugins,
                         const std::string& configPath);

// One warning per light and key where a --set of a per-light key does nothing because the
// light's own scene settings (RenderPlugin::sceneLightSettings) set that key and no
// per-light option does: naming the light, the key, the value that wins, and the option
// that would override it for that light.
std::vector<std::string> shadowedSettingWarnings(const std::vector<SettingOverride>& settings,
                                                 const std::vector<LightOverride>& resolved,
                                                 const engine::PluginHost& host, const engine::Scene& scene);

} // namespace tools
