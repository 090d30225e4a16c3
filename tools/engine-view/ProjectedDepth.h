#pragma once
// The "depth map projected onto the scene" view, on the CPU: for every covered pixel, the
// texel of the light's depth-map picture (DepthImage.h gray) that the light's ray through
// the pixel's surface point lands on, blended over the shaded image so the scene stays
// recognisable. Texels are looked up as the plugin's map was rendered:
//  - spot: L as the plugin reported it, P_light a perspective of fovy = 2 * outer cone
//    (at most 178 degrees) and aspect 1 (shadowmap_plugin/src/math/LightFrustum.h); s, t
//    do not depend on near/far, so reversed Z and infinite far planes need nothing special;
//  - point: a cube looked up as GL does (major axis, then the spec's sc/tc table) with the
//    direction surface - light position (the plugin's cube is world-axis aligned).
// Pixels the map does not cover (behind the light, outside the cone) are darkened.
#include "Image.h"

#include "truth/SurfaceCapture.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

struct ProjectedMap {
    enum class Kind { Spot, Cube } kind = Kind::Spot;
    glm::dmat4 lightToWorld{1.0};  // spot: L
    double halfAngle = 0.5;        // spot: half of fovy
    glm::dvec3 position{0.0};      // cube: the light's position
    int faceSize = 0;              // map texels per side (each face for a cube)
    // DepthImage's gray picture: width faceSize (x6 for a cube, faces side by side), top
    // row first.
    const std::vector<std::uint8_t>* gray = nullptr;
};

// `shaded` and `surfaces` are the same camera's image and capture.
Image projectDepthMap(const Image& shaded, const truth::SurfaceBuffer& surfaces, const ProjectedMap& map);
