#pragma once
// A shadow map as a picture (the "light's depth map" view of Kilgard's GDC 2000 slides): far (1.0, nothing drawn)
// is white, the drawn depths are stretched over [0, 230] so near is dark. Cube maps become
// a strip of six faces in GL order (+X, -X, +Y, -Y, +Z, -Z).
#include "engine/render/Renderer.h"

#include <cstdint>
#include <vector>

std::vector<std::uint8_t> depthToGray(const engine::DepthReadback& map, int& width, int& height);
