#pragma once
// The lit pass's lights as lit.frag reads them: the uniform block of eye-space light data
// (binding kLightsUniformBinding, std140) and the defines naming how many lights the pass
// shades and of which type; for the clustered lit pass (Frame.h), the same data for every
// light in a storage buffer, with each light's type and dimming, and the tile lists.
#include "engine/gl/Buffer.h"
#include "engine/render/Frame.h"
#include "engine/render/LightTiles.h"
#include "engine/scene/Scene.h"

#include <string>
#include <vector>

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

// The clustered lit pass's storage buffers: every light instance (lit.frag's LightData, its
// type code in direction.w and its dimming in cone.z) on kClusteredLightsBinding, the tiles'
// ranges on kLightTileRangesBinding and their lists on kTileLightsBinding. Each buffer grows
// (to the next power of two) when a frame needs more, and is never shrunk.
class ClusteredLights {
public:
    void upload(const Scene& scene, const FrameCamera& camera, const std::vector<float>& dimming,
                const LightTiles& tiles);
    void bind() const;

private:
    gl::Buffer lights_, ranges_, lists_;
};

// lit.frag's defines for the clustered lit pass: CLUSTERED_LIGHTS, its buffers' bindings and
// LIGHT_TILE_SIZE, and LIGHT_COUNT 0 (nothing is unrolled).
std::string clusteredLightDefines();

// lit.frag's light defines: LIGHT_COUNT, and FOR_EACH_LIGHT(F) expanding to F(slot, type
// code) for each light, unrolled with literal arguments, or (unrolled false) as one loop
// reading the types from a constant array.
std::string lightDefines(const Scene& scene, int lightCount, bool unrolled);

} // namespace engine
