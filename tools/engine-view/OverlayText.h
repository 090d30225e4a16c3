#pragma once
// What the overlay says: one line per light (variant, map size, depth format, size, filter,
// polygon offset, dimming, ms of its passes, cached or rendered, where the lit pass took its
// shade from), the frame's time, view
// and camera, the view's notes, a transient status message, and the keys.
#include "Overlay.h"
#include "ViewerState.h"

#include "engine/render/Renderer.h"

#include <map>
#include <string>
#include <vector>

namespace engine_view {

class OverlayText {
public:
    // Remembers each light's pass time of the frames that rendered its map, so a cached
    // light still shows what its map cost.
    void recordFrame(const engine::FrameResult& frame, const ViewerState& state);

    std::vector<OverlayLine> lines(const ViewerState& state, const engine::FrameResult& frame,
                                   const std::vector<std::string>& notes, const std::string& camera,
                                   const std::string& animation, const std::string& status, bool statusIsError) const;

    // Where the frame's lit pass took light `slot`'s shade from, from FrameResult::shadeCache:
    // "shade reused" (shade cache), "shade computed" (and cached), "shade live" (evaluated,
    // not cached), "shade constant", or "" when the frame does not say.
    static std::string shadeSource(const engine::ShadeCacheReport& shadeCache, int slot);

    // A light's size (light_radius, or angular_diameter for a directional light) beside its
    // filter, which it decides pcss by: "size 0.15", "size 0.0093 rad", or "point" for 0.
    static std::string lightSize(double size, engine::Light::Type type);

private:
    std::map<int, double> lastMs_;  // by light slot
};

} // namespace engine_view
