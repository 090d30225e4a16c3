#pragma once
// A shadow map as a picture (the "light's depth map" view of Kilgard's GDC 2000 slides): far (1.0, nothing drawn)
// is white, the drawn depths are stretched over [0, 230] so near is dark. Cube maps become
// a strip of six faces in GL order (+X, -X, +Y, -Y, +Z, -Z).
#include "engine/render/Renderer.h"

#include <cstdint>
#include <vector>

std::vector<std::uint8_t> depthToGray(const engine::DepthReadback& map, int& width, int& height);

// The names of a cube's faces in the strip's order (GL's: layer i is
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), as labelCubeFaces writes them.
extern const char* const kCubeFaceNames[engine::kCubeFaces];

// Writes each face's name (+X, -X, +Y, -Y, +Z, -Z) into the top-left corner of its face
// of a depthToGray strip, black on a white box with a black rule along the face's left
// edge, so a person reading the picture knows which face is which. Only for pictures: the
// labels cover depth texels, so nothing that measures the map reads a labelled strip.
void labelCubeFaces(std::vector<std::uint8_t>& gray, int width, int height, int faceWidth);
