#pragma once
// The lit pass's lights as lit.frag reads them: the uniform block of eye-space light data
// (binding kLightsUniformBinding, std140) and the defines naming how many lights the pass
// shades and of which type.
#include "engine/gl/Buffer.h"
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <string>

namespace engine {

class LitLights {
public:
    LitLights();
    // Fills the block with the scene's first kMaxLights light instances in eye space
    // (V^-1 * L composed in double, then cast).
    void upload(const Scene& scene, const FrameCamera& camera);
    unsigned buffer() const { return buffer_.id(); }

private:
    gl::Buffer buffer_;
};

// lit.frag's light defines: LIGHT_COUNT, and FOR_EACH_LIGHT(F) expanding to F(slot, type
// code) for each light, unrolled with literal arguments, or (unrolled false) as one loop
// reading the types from a constant array.
std::string lightDefines(const Scene& scene, int lightCount, bool unrolled);

} // namespace engine
