#pragma once
// Reads a texture back to the CPU in image order (top row first), as PNG files expect;
// GL stores row 0 at the bottom.
#include "engine/gl/Texture.h"

#include <cstdint>
#include <vector>

namespace engine {

std::vector<std::uint8_t> readTextureRGBA8TopDown(const gl::Texture& texture);
std::vector<float> readTextureFloatTopDown(const gl::Texture& texture, int channels);
// Every layer (cube faces in GL order, array layers) of a depth texture, each top row first.
std::vector<float> readDepthLayersTopDown(unsigned texture, int width, int height, int layers);
// One byte per texel of a one-channel 8-bit texture (R8), top row first.
std::vector<std::uint8_t> readR8TopDown(unsigned texture, int width, int height);

} // namespace engine
