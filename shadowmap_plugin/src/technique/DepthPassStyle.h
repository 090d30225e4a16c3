#pragma once
// How a depth pass draws the casters of one map layer: what differs between the ways of
// making a map (DepthTechnique.h) is a style, not another renderer (plugin/DepthRenderer.h
// draws every style).
#include "technique/DepthProgram.h"

#include "engine/graph/RenderGraph.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowmap {

class CasterLods;

// One float uniform of a depth program, by its GLSL name.
struct DepthUniform {
    const char* name;
    float value;
};

struct DepthPassStyle {
    // standard and woo: every face (open casters must cast too). backface: only faces
    // turned away from the light, for casters that are closed; open ones are drawn with
    // both faces (and openCasterOffset) so their shadow stays right.
    bool backFacesOnly = false;
    glm::vec2 polygonOffset{0.0f};      // for every draw (standard; both woo passes), or none
    glm::vec2 openCasterOffset{0.0f};   // backface: the offset for two-sided open casters
    const std::vector<bool>* closedMeshes = nullptr;  // backface: per Scene::meshes
    // The program the casters are drawn with (DepthProgram.h), and what it reads: a texture
    // bound at its DEPTH_INPUT_UNIT (0: none) and float uniforms (Woo pass 2: the first
    // layer's depth and the peel's epsilon).
    const DepthProgram* program = &nearestDepthProgram();
    // Also draw the receivers that cast no shadow (a --ground, a glTF cast_shadows: false):
    // Woo's peel, whose second layer must see them (DepthTechnique::drawsNonCastingReceivers).
    bool drawsNonCastingReceivers = false;
    // Cull back faces of single-sided materials, as the lit pass draws them: the camera's depth
    // for shadow volumes must hold the surface the lit pass will shade (plugin/VolumeRenderer.h).
    bool cullsSingleSidedBackFaces = false;
    unsigned inputTexture = 0;
    std::vector<DepthUniform> uniforms;
    // Reversed Z (ShadowSettings reversed_z, d32f): glClipControl(GL_LOWER_LEFT,
    // GL_ZERO_TO_ONE) for the pass, clear depth 0, GL_GREATER depth test, polygon offsets
    // negated (away from the light is toward 0).
    bool reversedZ = false;
    // > 0: glPolygonOffsetClamp's clamp, in window depth (ShadowSettings
    // polygon_offset_clamp converted per light); 0: plain glPolygonOffset.
    float offsetClamp = 0.0f;
    // Per Scene::meshInstances: casters this layer leaves out, their shadow reaching no visible
    // receiver (UnseenShadows.h); null: none.
    const std::vector<bool>* unseenCasters = nullptr;
    // caster_lod: each caster's levels (plugin/CasterLods.h) and the largest error a drawn
    // level may have, as a fraction of one of the map's texels (resolution across) at the
    // caster (technique/CasterLodChoice.h); null or 0: every caster as loaded.
    const CasterLods* casterLods = nullptr;
    double lodTexelFraction = 0.0;
    int mapResolution = 0;
    // A map in a shadow atlas (plugin/AtlasMaps.h): the pass renders, clears and writes only
    // this square of the shared texture (x, y its lower corner, size texels per side);
    // size 0: the whole target.
    struct Viewport {
        int x = 0, y = 0, size = 0;
    };
    Viewport atlasViewport;
    bool inAtlas() const { return atlasViewport.size > 0; }
};

// The state a depth pass of this style declares (engine/graph/PassState.h): depth test and
// clip range for the depth direction, the offset, and front-face culling for backface
// (switched per caster: closed casters only).
engine::PassState depthPassState(const DepthPassStyle& style);
// The target of such a pass: `layer` of `map` (-1: a 2D map), cleared to the far depth.
engine::PassTargets depthPassTargets(engine::ResourceHandle map, int layer, const DepthPassStyle& style);

// Reversed Z stores near as 1 and far as 0: "away from the light" is then a negative
// offset, and glPolygonOffsetClamp's clamp must carry the same sign (a negative clamp is a
// lower bound). (factor, units, clamp) as GL takes them.
glm::vec3 signedOffset(const glm::vec2& offset, const DepthPassStyle& style);

} // namespace shadowmap
