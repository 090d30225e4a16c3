#pragma once
// The lit pass's lights as lit.frag reads them: the uniform block of eye-space light data
// (binding kLightsUniformBinding, std140) and the defines naming how many lights the pass
// shades and of which type; for the clustered lit pass (Frame.h), the same data for every
// light in a texture, with each light's type and dimming, and the tile lists.
#include "engine/gl/Buffer.h"
#include "engine/gl/Texture.h"
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

// The clustered lit pass's textures: every light instance as four RGBA32F texels of a row
// (lit.frag's LightData, its type code in direction.w and its dimming in cone.z) on
// kLightDataUnit, each tile's (first, count) as an RG32UI texel at the tile's place on
// kTileRangesUnit, and the lists on kTileLightsUnit (R32UI, kTileListsWidth per row). Each
// texture grows when a frame needs more and is never shrunk.
class ClusteredLights {
public:
    void upload(const Scene& scene, const FrameCamera& camera, const std::vector<float>& dimming,
                const LightTiles& tiles);
    void bind() const;

private:
    gl::Texture lights_, ranges_, lists_;
};

// lit.frag's defines for the clustered lit pass: CLUSTERED_LIGHTS, its textures' units,
// LIGHT_TILE_SIZE and TILE_LISTS_WIDTH, and LIGHT_COUNT 0 (nothing is unrolled).
std::string clusteredLightDefines();

// lit.frag's light defines: LIGHT_COUNT, and FOR_EACH_LIGHT(F) expanding to F(slot, type
// code) for each light, unrolled with literal arguments, or (unrolled false) as one loop
// reading the types from a constant array.
std::string lightDefines(const Scene& scene, int lightCount, bool unrolled);

} // namespace engine
