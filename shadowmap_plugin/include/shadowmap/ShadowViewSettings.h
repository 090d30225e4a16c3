#pragma once
// A light's shadow settings as the plugin used them in a frame, read back from the
// engine::ShadowView it published (engine/render/ShadowView.h). ShadowView::settings is JSON
// because the engine knows no plugin's types; these read it through the settings API
// (ShadowSettings.h), so tools never look up its keys or compare its values as strings.
#include "shadowmap/ShadowSettings.h"

#include "engine/render/ShadowView.h"

#include <nlohmann/json.hpp>

namespace shadowmap {

// What the plugin puts in ShadowView::settings: printSettings() of `settings` with the
// polygon offset made explicit, the one its depth pass used (the variant's default when
// none was set), so a reader needs no rule for defaults.
nlohmann::json printUsedSettings(const ShadowSettings& settings);

// The settings `view` was rendered with: parseSettings(view.settings). polygonOffset is
// always set (to the effective offset), so effectivePolygonOffset() is the used one.
// engine::InputError if the view holds what the settings API does not accept.
ShadowSettings usedSettings(const engine::ShadowView& view);
// usedSettings(view).variant.
Variant usedVariant(const engine::ShadowView& view);

} // namespace shadowmap
