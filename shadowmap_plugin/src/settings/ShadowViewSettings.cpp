// Settings in a published ShadowView (shadowmap/ShadowViewSettings.h): written by the
// plugin and read by the tools with one printer and one parser, so they cannot drift apart.
#include "shadowmap/ShadowViewSettings.h"

#include <string>

namespace shadowmap {

nlohmann::json printUsedSettings(const ShadowSettings& settings) {
    ShadowSettings used = settings;
    used.polygonOffset = settings.effectivePolygonOffset();
    return printSettings(used);
}

ShadowSettings usedSettings(const engine::ShadowView& view) {
    // Error messages name the view's light: the JSON came from the plugin, not a file.
    return parseSettings(view.settings, "shadow view", "light \"" + view.name + "\"");
}

Variant usedVariant(const engine::ShadowView& view) { return usedSettings(view).variant; }

} // namespace shadowmap
