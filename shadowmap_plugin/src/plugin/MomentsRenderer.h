#pragma once
// Draws the moments passes of filterable maps (vsm, evsm; technique/lookup/MomentsLookup.h)
// inside passes whose target (a layer of the moments, or the rows between the two blur
// passes) the graph binds: full-screen triangles through the programs of shaders/moments/.
// plugin/MomentsPasses.h declares the passes.
#include "engine/gl/Program.h"
#include "engine/gl/Sampler.h"
#include "engine/gl/VertexArray.h"

#include <glm/glm.hpp>

#include <map>

namespace shadowmap {

// How one layer's window depths become the moments' depth (shaders/moments/moments.glsl).
struct MomentsDepth {
    bool perspective = false;
    bool reversed = false;
    float nearPlane = 0.0f, farPlane = 0.0f;  // perspective only
    bool evsm = false;
    glm::vec2 exponents{0.0f};  // evsm's [positive, negative]
};

class MomentsRenderer {
public:
    // Compiles the blur; the first pass's program per kind of layer (vsm or evsm,
    // perspective or not, reversed or not) is compiled by prepare, or else with the first
    // layer of its kind.
    MomentsRenderer();

    // Compiles the first pass's program for layers of this kind (only its flags count), so
    // that a light whose map first renders after warm-up compiles nothing then.
    void prepare(const MomentsDepth& kind) const { fromDepthProgram(kind); }

    // The moments of layer `layer` of `mapLayers` (the map as a 2D array), box-blurred by
    // `radius` texels along `step` (radius 0: each texel's own).
    void fromDepth(unsigned mapLayers, int layer, const MomentsDepth& depth, float radius, glm::ivec2 step) const;
    // `rows` (what fromDepth wrote) blurred by `radius` texels along `step`.
    void blur(unsigned rows, float radius, glm::ivec2 step) const;

private:
    const engine::gl::Program& fromDepthProgram(const MomentsDepth& depth) const;

    mutable std::map<unsigned, engine::gl::Program> fromDepth_;  // by kind of layer (kindOf)
    engine::gl::Program blur_;
    // Texels as stored: no comparison (the depth map compares on its own state), and
    // complete whatever the source's filters (texelFetch of an incomplete texture reads 0).
    engine::gl::Sampler texelSampler_;
    engine::gl::VertexArray empty_;
};

} // namespace shadowmap
