#pragma once
// Renders depth from one light view into one layer of a shadow map: the depth pass every
// variant and light type shares (spot and directional: the 2D map; point: one cube face).
// What differs between variants is a DepthPassStyle, not another renderer.
#include "engine/gl/FramebufferCache.h"
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
    // Woo pass 2: the nearest-layer depth to peel against (0: not peeling). A 2D texture,
    // or a 2D array with one layer per cube face when firstLayerIsArray.
    unsigned firstLayer = 0;
    bool firstLayerIsArray = false;
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

struct DepthDrawCounts {
    std::uint64_t draws = 0, triangles = 0, castersCulled = 0;
};

class DepthRenderer {
public:
    DepthRenderer();

    // Within a pass in depthPassState(style): clears `layer` of `target` (-1: a 2D texture)
    // to the far depth and, when drawCasters,
    // draws every shadow caster of the frame's scene whose bounds meet viewProjection =
    // P_light * L^-1. Counts draws in `context` (the graph's per-pass report).
    DepthDrawCounts render(const engine::Frame& frame, engine::PassContext& context,
                           unsigned target, int layer, const glm::dmat4& viewProjection, const DepthPassStyle& style,
                           bool drawCasters = true);

private:
    enum class Peel { None, Layer2D, LayerArray };
    // The program for a peel kind and a caster's material features (MaterialShading.h:
    // only alpha-tested casters have any), compiled on first use: a scene without such
    // casters never builds (or pays for) one that can discard.
    const engine::gl::Program& program(Peel peel, unsigned materialFeatures);

    std::map<std::pair<Peel, unsigned>, engine::gl::Program> programs_;
    engine::gl::VertexArray empty_;  // for the Woo far-layer triangle (gl_VertexID only)
    engine::gl::FramebufferCache framebuffers_;  // one per map and face or layer
};

} // namespace shadowmap
