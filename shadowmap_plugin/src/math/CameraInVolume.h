#pragma once
// Whether a caster's shadow volume may hold the camera, which decides how the volume is
// counted: z-pass (the volume faces in front of each pixel's surface; no caps needed, the less
// geometry) is right only for a volume that holds no point of the camera's near plane or eye,
// since it counts from the eye; z-fail (the faces behind the surface, caps needed) is right
// always (Everitt and Kilgard 2002, section 5.4: their near-plane clip volume).
//
// Conservative, in world space, by spheres: the camera's eye and near-plane rectangle lie in a
// sphere of radius r around the rectangle's centre C. A volume point Q holds the camera only if
// the segment from Q to the light (the ray toward a directional light) meets the caster, at a
// point X; Q within r of C puts X within r of the segment from C to the light (the same
// fraction along both segments), and X lies within the caster's bounding sphere. So a caster's
// sphere farther than r from that segment cannot cast a volume that holds the camera.
#include <glm/glm.hpp>

namespace shadowmap {

struct CameraRegion {
    glm::dvec3 center{0.0};  // the near-plane rectangle's centre, world
    double radius = 0.0;     // holds the eye and the rectangle's corners
};

// The region of a perspective camera (projection: OpenGL's, any far plane or none).
CameraRegion cameraRegion(const glm::dmat4& eyeToWorld, const glm::dmat4& projection);

// light: world space, (position, 1) or (direction toward the light, 0). casterCenter/Radius: a
// sphere holding the caster. True when its volume may hold a point of the region.
bool volumeMayHoldCamera(const glm::dvec4& light, const CameraRegion& camera, const glm::dvec3& casterCenter,
                         double casterRadius);

} // namespace shadowmap
