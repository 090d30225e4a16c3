#pragma once
// What a tool writes as a light's extras.shadow when it saves settings into the scene
// (engine-view --save-settings, shadowmap-tune --out), one rule for both: the keys the
// loaded file already had stay (the author's choice, as they are now), and of the keys the
// tool set only those whose value changes what the defaults give (built-in <- the engine
// config's plugin settings, compared through the shadow plugin's settings API), so a later
// change of the config still reaches every setting nobody chose.
#include <nlohmann/json.hpp>

namespace tools {

// `configSettings`: the shadow plugin's settings object in the engine config (plugin-wide
// keys such as cache_maps are ignored); `loaded`: the light's extras.shadow as the file had
// it (an object, empty for none); `current`: the extras.shadow the tool has now.
nlohmann::json savedShadow(const nlohmann::json& configSettings, const nlohmann::json& loaded,
                           const nlohmann::json& current);

} // namespace tools
