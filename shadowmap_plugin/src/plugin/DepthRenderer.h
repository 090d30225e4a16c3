#pragma once
// Draws the shadow casters from one light view, inside a depth pass whose state and target
// (one layer of a shadow map: spot and directional the 2D map, point one cube face; or
// Woo's first layer) the graph applies: the drawing every variant and light type shares.
// What differs between variants is a DepthPassStyle, not another renderer.
#include "engine/gl/Program.h"
#include "engine/gl/VertexArray.h"
#include "engine/render/Frame.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace shadowmap {

struct DepthPassStyle {
    // standard and woo: every face (open casters must cast too). backface: only faces
    // turned away from the light, for casters that are closed; open ones are drawn with
    // both faces (and openCasterOffset) so their shadow stays right.
    bool backFacesOnly = false;
    glm::vec2 polygonOffset{0.0f};      // for every draw (standard; both woo passes), or none
    glm::vec2 openCasterOffset{0.0f};   // backface: the offset for two-sided open casters
    const std::vector<bool>* closedMeshes = nullptr;  // backface: per Scene::meshes
    // Woo pass 2: the nearest-layer depth to peel against (0: not peeling), a 2D texture of
    // the map's size (one per cube face).
    unsigned firstLayer = 0;
    float peelEpsilon = 0.0f;  // depth within which a fragment counts as the first layer
                               // (reversedZ: relative to the first layer's depth)
    // Reversed Z (ShadowSettings reversed_z, d32f): glClipControl(GL_LOWER_LEFT,
    // GL_ZERO_TO_ONE) for the pass, clear depth 0, GL_GREATER depth test, polygon offsets
    // negated (away from the light is toward 0).
    bool reversedZ = false;
    // > 0: glPolygonOffsetClamp's clamp, in window depth (ShadowSettings
    // polygon_offset_clamp converted per light); 0: plain glPolygonOffset.
    float offsetClamp = 0.0f;
};

// The state a depth pass of this style declares (engine/graph/PassState.h): depth test and
// clip range for the depth direction, the offset, and front-face culling for backface
// (switched per caster: closed casters only).
engine::PassState depthPassState(const DepthPassStyle& style);
// The target of such a pass: `layer` of `map` (-1: a 2D map), cleared to the far depth.
engine::PassTargets depthPassTargets(engine::ResourceHandle map, int layer, const DepthPassStyle& style);

struct DepthDrawCounts {
    std::uint64_t draws = 0, triangles = 0, castersCulled = 0;
};

class DepthRenderer {
public:
    DepthRenderer();

    // Within a pass in depthPassState(style), drawing into depthPassTargets(...): draws every
    // shadow caster of the frame's scene whose bounds meet viewProjection = P_light * L^-1
    // (and, when peeling, the far plane as the last layer). Counts draws in `context` (the
    // graph's per-pass report).
    DepthDrawCounts draw(const engine::Frame& frame, engine::PassContext& context,
                         const glm::dmat4& viewProjection, const DepthPassStyle& style);

private:
    // The program for peeling or not and a caster's material features (MaterialShading.h:
    // only alpha-tested casters have any), compiled on first use: a scene without such
    // casters never builds (or pays for) one that can discard.
    const engine::gl::Program& program(bool peel, unsigned materialFeatures);

    std::map<std::pair<bool, unsigned>, engine::gl::Program> programs_;
    engine::gl::VertexArray empty_;  // for the Woo far-layer triangle (gl_VertexID only)
};

} // namespace shadowmap
