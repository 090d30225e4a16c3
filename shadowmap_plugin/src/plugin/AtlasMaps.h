#pragma once
// The shadow maps of a frame shaded by the clustered lit pass (engine/render/Frame.h): its
// visibility hook indexes lights by a slot that is not a constant, so every map lives in one
// depth texture, the atlas (math/ShadowAtlas.h lays it out), read through one texture unit,
// and every light's lookup parameters in another (shaders/atlas_visibility.glsl).
//
// What the atlas holds today: spot lights' single 2D maps, drawn by the standard or backface
// technique and read with the hardware comparison (nearest or 2x2 pcf), in one depth format
// and direction. Every other light of such a frame is lit without a shadow, and a light
// whose settings ask for something else (woo, another filter, format or depth direction) is
// drawn as the atlas draws; each says so once (the plugin's warnings).
//
// A light's map keeps its rectangle and contents while its light and casters keep still
// (the map cache's key, as for a light's own texture); the atlas says which maps moved or
// are new, and only those and the maps whose key changed are drawn.
#include "plugin/CasterLods.h"
#include "plugin/DepthRenderer.h"
#include "plugin/LightShadow.h"
#include "math/ShadowAtlas.h"
#include "technique/MapProjection.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Sampler.h"
#include "engine/gl/Texture.h"
#include "engine/render/Frame.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace shadowmap {

// The widest map the atlas gives a light; the atlas grows to hold its maps up to this side.
inline constexpr int kMaxAtlasSize = 8192;
// The atlas's lookup (the 2x2 hardware comparison) is clamped half a texel inside a map's
// rectangle (atlas_visibility.glsl), so it reads no texel outside it: one texel of border
// only keeps a rasterizer's stray edge pixel off a neighbour (the passes scissor too).
inline constexpr int kAtlasLookupBorderTexels = 1;
// The smallest block a map gets (a 14-texel map): a light the camera sees only as a few pixels
// still gets a map whose texels hold its casters' outline to a pixel or two.
inline constexpr std::int64_t kMinAtlasBlock = 16;
// A map moves to the next smaller block only when that block's map is this much larger
// than what it needs: the needed size must fall to 0.4 of the current map, so a size near a
// block's edge does not flicker between two (each change redraws the map).
inline constexpr double kShrinkMargin = 1.25;

struct AtlasFrameCounts {
    int rendered = 0;  // maps drawn this frame
    int cached = 0;    // maps kept from an earlier frame
};

class AtlasMaps {
public:
    using Warn = std::function<void(const LightShadow&, const std::string&)>;

    // A new scene or new settings: the resolutions asked for are read again on the next frame.
    void reset();

    // Plans every light (planLight), places the maps of the lights the atlas holds and adds
    // the depth passes of those whose map is not still right; returns the atlas's version the
    // lit pass reads (invalid when no light has a map this frame).
    engine::ResourceHandle addPasses(engine::Frame& frame, std::vector<LightShadow>& lights,
                                     const PlanContext& context, DepthRenderer& renderer,
                                     const std::vector<bool>& closedMeshes, const CasterLods* casterLods,
                                     std::vector<std::vector<std::uint64_t>>& levelDraws,
                                     std::uint64_t sceneGeneration, bool cacheMaps, const Warn& warn);

    // The clustered lit pass's hook for this frame's lights (after addPasses).
    engine::LightVisibilityHook hook(const engine::Frame& frame, const std::vector<LightShadow>& lights,
                                     engine::ResourceHandle atlas);

    const AtlasFrameCounts& counts() const { return counts_; }
    // --stats: the atlas's side, its occupancy and what it did this frame.
    nlohmann::json stats() const;

private:
    // Makes `light`'s settings the atlas's (variant, filter, format, depth direction), saying
    // what it changed; false if the atlas cannot hold its map at all.
    bool conform(LightShadow& light, const Warn& warn);
    // The block (a power of two, border included) of a light's map: the smallest whose map's
    // texels span at most a pixel where the light reaches what the camera sees
    // (math/ScreenMatchedResolution.h), at most the block of the resolution it asked for, and
    // kept when it would shrink by less than kShrinkMargin.
    std::int64_t screenMatchedBlock(const LightShadow& light, const PlanContext& context) const;
    // The side of each held light's map (screenMatchedBlock's) and of each kept one (a light
    // off screen: its last block), halving the largest until their blocks fit kMaxAtlasSize;
    // remembers the blocks for the next frame's hysteresis.
    std::vector<AtlasRequest> requests(const std::vector<const LightShadow*>& held,
                                       const std::vector<const LightShadow*>& kept, const PlanContext& context);
    void ensureTexture(int size);

    std::optional<ShadowAtlas> allocator_;
    engine::gl::Texture texture_;
    engine::gl::Texture lightData_;  // atlas_visibility.glsl's AtlasLight rows
    engine::gl::Sampler rawDepthSampler_;
    std::vector<int> requestedResolution_;  // by slot: what the light's settings asked for
    std::vector<std::int64_t> previousBlock_;  // by slot: last frame's block (0: none)
    bool formatChosen_ = false;
    DepthFormat format_ = DepthFormat::D24;
    bool reversedZ_ = false, bilinear_ = true;
    AtlasFrameCounts counts_;
};

} // namespace shadowmap
