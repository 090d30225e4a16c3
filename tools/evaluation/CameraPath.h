#pragma once
// The camera path shimmer is measured on (truth/Shimmer.h), shared by shadowmap-bench and
// shadowmap-stress: `frames` views starting at `camera`, panning one pixel per frame. A
// perspective camera turns about its own up axis by the angle of the pixel at the image's
// centre, an orthographic one moves sideways by a pixel, so the surface points near the
// centre column (perspective) or everywhere (orthographic) land on pixel centres of the next
// frame, where shimmer compares them.
#include "engine/render/Frame.h"

#include <vector>

namespace evaluation {

std::vector<engine::FrameCamera> onePixelPan(const engine::FrameCamera& camera, int frames);

} // namespace evaluation
