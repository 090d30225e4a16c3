#pragma once
// variant volume: the graph pass that makes a light's visibility per camera pixel
// (VolumeRenderer.h) into its visibility texture, which the lit pass reads at the pixel
// instead of a map. No pass when the camera, the light and every mesh are as when the texture
// was last made (a cache hit, as for maps).
#include "plugin/DepthRenderer.h"
#include "plugin/LightShadow.h"
#include "plugin/VolumeRenderer.h"

#include "engine/render/Frame.h"

#include <cstdint>

namespace shadowmap {

// The visibility texture in this frame's graph, at the version the lit pass reads.
engine::ResourceHandle addVolumePass(LightShadow& light, engine::Frame& frame, VolumeRenderer& volumes,
                                     DepthRenderer& depth, std::uint64_t sceneGeneration, bool cache);

} // namespace shadowmap
