#include "math/CameraInVolume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowmap {

namespace {

// A relative margin on the distances compared, far above their rounding in double (about 1e-16
// of the scene's extent) and far below any clearance that matters.
constexpr double kMargin = 1e-6;

} // namespace

CameraRegion cameraRegion(const glm::dmat4& eyeToWorld, const glm::dmat4& projection) {
    const glm::dmat4 clipToEye = glm::inverse(projection);
    glm::dvec3 corners[4];
    glm::dvec3 center(0.0);
    int k = 0;
    for (const double x : {-1.0, 1.0})
        for (const double y : {-1.0, 1.0}) {
            const glm::dvec4 p = clipToEye * glm::dvec4(x, y, -1.0, 1.0);
            corners[k] = glm::dvec3(p) / p.w;
            center += corners[k++] * 0.25;
        }
    double radius = glm::length(center);  // the eye, at the eye-space origin
    for (const glm::dvec3& corner : corners) radius = std::max(radius, glm::length(corner - center));
    return {glm::dvec3(eyeToWorld * glm::dvec4(center, 1.0)), radius};
}

bool volumeMayHoldCamera(const glm::dvec4& light, const CameraRegion& camera, const glm::dvec3& casterCenter,
                         double casterRadius) {
    if (!std::isfinite(casterRadius) || !std::isfinite(camera.radius)) return true;
    // The segment (or ray) from the region's centre toward the light, and the point of it
    // nearest the caster's centre.
    const glm::dvec3 toLight = light.w == 0.0 ? glm::dvec3(light) : glm::dvec3(light) / light.w - camera.center;
    const double length2 = glm::dot(toLight, toLight);
    if (!(length2 > 0.0)) return true;  // a light at the camera: every volume may hold it
    const double upper = light.w == 0.0 ? std::numeric_limits<double>::infinity() : 1.0;
    const double along = std::clamp(glm::dot(casterCenter - camera.center, toLight) / length2, 0.0, upper);
    const double distance = glm::length(camera.center + along * toLight - casterCenter);
    const double reach = (camera.radius + casterRadius) * (1.0 + kMargin);
    return !(distance > reach);
}

} // namespace shadowmap
