#pragma once
// Renders depth from one light view into one layer of a shadow map: the depth pass every
// variant and light type shares (spot and directional: the 2D map; point: one cube face).
#include "plugin/ShadowSettings.h"

#include "engine/gl/Program.h"
#include "engine/render/Frame.h"

#include <glm/glm.hpp>

namespace shadowmap {

struct DepthDrawCounts {
    std::uint64_t draws = 0, triangles = 0, castersCulled = 0;
};

class DepthRenderer {
public:
    DepthRenderer();

    // Clears `layer` of `map` (-1: a 2D map) to the far depth and, when drawCasters, draws
    // every shadow caster of the frame's scene whose bounds meet viewProjection =
    // P_light * L^-1, with the settings' polygon offset. Counts draws in `context` (the
    // graph's per-pass report). A cube face that sees no receiver is only cleared.
    DepthDrawCounts render(const engine::Frame& frame, engine::PassContext& context,
                           unsigned map, int layer, int resolution,
                           const glm::dmat4& viewProjection, const ShadowSettings& settings,
                           bool drawCasters = true);

private:
    engine::gl::Program program_;
};

} // namespace shadowmap
