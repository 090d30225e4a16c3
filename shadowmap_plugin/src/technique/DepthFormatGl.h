#pragma once
// What a depth format (shadowmap/ShadowSettings.h) means to GL and to the render graph.
#include "shadowmap/ShadowSettings.h"

#include "engine/graph/TextureDesc.h"

namespace shadowmap {

unsigned glInternalFormat(DepthFormat format);
// The depth step of a format near 1 (fixed point: 1/(2^bits - 1); d32f: 2^-24).
double depthStep(DepthFormat format);
engine::TextureFormat graphFormat(DepthFormat format);

} // namespace shadowmap
