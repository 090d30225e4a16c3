#pragma once
// One light's shadow as the plugin keeps it: the GL-free state (technique/LightState.h) and
// its depth map (a 2D texture, a 2D array of one layer per cascade, or a cube, as its
// projection's MapShape says), owned here so it can outlive a frame.
#include "technique/LightState.h"

#include "engine/gl/Texture.h"
#include "engine/render/ShadowView.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadowmap {

struct LightShadow : LightState {
    engine::gl::Texture map;

    // (Re)creates the map when size, format or shape changed (a new texture holds nothing:
    // its rendered keys are reset), with the comparison state and filter the lookup needs.
    void ensureMap();
    // --stats' summary of the settings in effect, keyed as in extras.shadow (the tools read
    // ShadowView::settings instead, through shadowmap/ShadowViewSettings.h).
    nlohmann::json settingsJson() const;
    nlohmann::json stats() const;
    // What the tools see of this light this frame (ShadowView.h).
    engine::ShadowView view() const;
};

} // namespace shadowmap
