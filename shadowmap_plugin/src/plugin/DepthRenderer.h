#pragma once
// Draws the shadow casters from one light view, inside a depth pass whose state and target
// (one layer of a shadow map: spot and directional the 2D map, point one cube face; or
// Woo's first layer) the graph applies: the drawing every variant and light type shares.
// What differs between variants is a DepthPassStyle and its DepthProgram, not another
// renderer.
#include "technique/DepthPassStyle.h"

#include "engine/gl/Program.h"
#include "engine/gl/VertexArray.h"
#include "engine/render/Frame.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace shadowmap {

struct DepthDrawCounts {
    std::uint64_t draws = 0, triangles = 0, castersCulled = 0, castersUnseen = 0;
    std::vector<std::uint64_t> levelDraws;  // caster_lod: draws per level (0: as loaded)
};

class DepthRenderer {
public:
    // Compiles every technique's depth programs for opaque casters.
    DepthRenderer();

    // Within a pass in depthPassState(style), drawing into depthPassTargets(...): draws every
    // shadow caster of the frame's scene whose bounds meet viewProjection = P_light * L^-1
    // with style.program (and its full-screen layer last, if it has one). Counts draws in
    // `context` (the graph's per-pass report).
    DepthDrawCounts draw(const engine::Frame& frame, engine::PassContext& context,
                         const glm::dmat4& viewProjection, const DepthPassStyle& style);

private:
    // A depth program built for a caster's material features (MaterialShading.h: only
    // alpha-tested casters have any), compiled on first use: a scene without such casters
    // never builds (or pays for) one that can discard.
    const engine::gl::Program& program(const DepthProgram& depthProgram, unsigned materialFeatures);

    std::map<std::pair<const DepthProgram*, unsigned>, engine::gl::Program> programs_;
    engine::gl::VertexArray empty_;  // for a full-screen layer (gl_VertexID only)
};

} // namespace shadowmap
