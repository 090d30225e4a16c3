#pragma once
// One light's shadow as the plugin keeps it: the GL-free state (technique/LightState.h) and
// its depth map (a 2D texture, a 2D array of one layer per cascade, or a cube, as its
// projection's MapShape says), owned here so it can outlive a frame.
#include "technique/LightState.h"

#include "engine/gl/Query.h"
#include "engine/gl/Texture.h"
#include "engine/render/ShadowView.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadowmap {

struct LightShadow : LightState {
    engine::gl::Texture map;
    // vsm, evsm (technique/lookup/MomentsLookup.h): the moments the lookup reads, shaped as
    // the map (a 2D map's with mipmaps when moments_mipmaps), and the map seen as a 2D array
    // (a texture view: a 2D map as one layer, a cube's six faces as six) for the passes that
    // make them. Empty for the other filters.
    engine::gl::Texture moments;
    engine::gl::Texture mapLayers;
    // volume (plugin/VolumePasses.h): 1 where the light reaches the camera's pixel, else 0
    // (R8, the camera's size), and the key of what it was last made from (0: nothing).
    engine::gl::Texture visibility;
    std::uint64_t visibilityKey = 0;
    // volume: counts the volume faces' samples that changed the stencil count (those behind
    // the nearest surface) in the light's last volume pass: its fill, for --stats.
    engine::gl::Query volumeFill;
    // volume, made only for a frame that reads the light's map back (a viewer's map view): the
    // count of volumes holding each camera pixel's surface (R8), and the key it was made for.
    engine::gl::Texture stencilCount;
    std::uint64_t stencilCountKey = 0;

    // (Re)creates the map when size, format or shape changed (a new texture holds nothing:
    // its rendered keys are reset), with the comparison state and filter the lookup needs.
    void ensureMap();
    // After ensureMap: the same for the moments and the map's layer view, or frees them when
    // the lookup reads none.
    void ensureMoments();
    engine::TextureDesc momentsDesc() const;
    // volume: (re)creates the visibility texture at the camera's size.
    void ensureVisibility(int width, int height);
    void ensureStencilCount(int width, int height);
    // --stats' summary of the settings in effect, keyed as in extras.shadow (the tools read
    // ShadowView::settings instead, through shadowmap/ShadowViewSettings.h).
    nlohmann::json settingsJson() const;
    nlohmann::json stats() const;
    // What the tools see of this light this frame (ShadowView.h).
    engine::ShadowView view() const;
};

} // namespace shadowmap
