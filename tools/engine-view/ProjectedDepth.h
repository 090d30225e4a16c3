#pragma once
// The "depth map projected onto the scene" view, on the CPU: for every covered pixel, the
// texel of the light's depth-map picture (DepthImage.h gray) that the light's ray through
// the pixel's surface point lands on, blended over the shaded image so the scene stays
// recognisable. Texels are looked up as the plugin's map was rendered:
//  - spot and directional (a 2D map): P_light * L^-1 of the light's shadow view, the
//    matrix the map was rendered with; s, t = clip x, y over w (only w > 0: nothing behind
//    the light), so reversed Z and infinite far planes need nothing special;
//  - point: a cube looked up as GL does (major axis, then the spec's sc/tc table) with the
//    direction surface - light position (the plugin's cube is world-axis aligned).
// Pixels the map does not cover (behind the light, outside the cone) are darkened.
#include "Image.h"

#include "truth/SurfaceCapture.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace engine_view {

struct ProjectedMap {
    enum class Kind { Map2D, Cube } kind = Kind::Map2D;
    glm::dmat4 viewProjection{1.0};  // 2D map: P_light * L^-1
    glm::dvec3 position{0.0};      // cube: the light's position
    int faceSize = 0;              // map texels per side (each face for a cube)
    // DepthImage's gray picture: width faceSize (x6 for a cube, faces side by side), top
    // row first.
    const std::vector<std::uint8_t>* gray = nullptr;
};

// `shaded` and `surfaces` are the same camera's image and capture.
Image projectDepthMap(const Image& shaded, const truth::SurfaceBuffer& surfaces, const ProjectedMap& map);

} // namespace engine_view
