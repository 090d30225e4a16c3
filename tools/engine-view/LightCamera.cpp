#include "LightCamera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace engine_view {

namespace {

constexpr double kDegree = 0.017453292519943295;

// A rigid eye -> world looking from `eye` along `direction`, up the world axis least
// parallel to it.
glm::dmat4 lookAlong(const glm::dvec3& eye, const glm::dvec3& direction) {
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec3 up = std::abs(d.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
    return glm::inverse(glm::lookAt(eye, eye + d, up));
}

// The scene's bounds in the eye space of `eyeToWorld` (x, y, and depth along -Z).
engine::Aabb boundsInEye(const engine::Scene& scene, const glm::dmat4& eyeToWorld) {
    engine::Aabb box;
    if (scene.worldBounds.empty()) return {glm::dvec3(-1.0, -1.0, 0.1), glm::dvec3(1.0, 1.0, 10.0)};
    const glm::dmat4 view = glm::inverse(eyeToWorld);
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 p = glm::dvec3(view * glm::dvec4(scene.worldBounds.corner(i), 1.0));
        p.z = -p.z;  // depth
        box.extend(p);
    }
    return box;
}

glm::dmat4 perspectiveOverBounds(const engine::Scene& scene, const glm::dmat4& eyeToWorld, double fovy) {
    const engine::Aabb box = boundsInEye(scene, eyeToWorld);
    const double radius = scene.worldBounds.empty() ? 1.0 : glm::length(scene.worldBounds.extent()) * 0.5;
    const double far = std::max(box.max.z * 1.01, radius * 1e-3);
    return glm::perspective(fovy, 1.0, std::max(box.min.z, far * 1e-4), far);
}

// L (light -> world) of the light's 2D map; false when it has none this frame.
bool mapLightToWorld(const engine::ShadowView* shadow, glm::dmat4& lightToWorld) {
    if (!shadow || !shadow->hasMap || shadow->cube || shadow->layers.empty()) return false;
    lightToWorld = shadow->layers.front().lightToWorld;
    return true;
}

} // namespace

engine::FrameCamera lightCamera(const engine::Scene& scene, int slot, const engine::ShadowView* shadow, int size) {
    const engine::LightInstance& placed = scene.lightInstances.at(slot);
    const engine::Light& light = scene.lights.at(placed.light);
    engine::FrameCamera camera;
    camera.width = camera.height = size;
    const glm::dvec3 center = scene.worldBounds.empty() ? glm::dvec3(0.0) : scene.worldBounds.center();
    const double radius = scene.worldBounds.empty() ? 1.0 : std::max(glm::length(scene.worldBounds.extent()) * 0.5, 1e-6);
    glm::dmat4 reported{1.0};
    const bool hasReported = mapLightToWorld(shadow, reported);

    switch (light.type) {
    case engine::Light::Type::Spot: {
        camera.eyeToWorld = hasReported ? reported : lookAlong(placed.position(), placed.direction());
        // The map's own field of view when it has one (the plugin may have narrowed the
        // cone); else the cone's, kept under the 180 degrees a perspective allows.
        const double fovy = hasReported ? 2.0 * std::atan(1.0 / shadow->layers.front().projection[1][1])
                                        : std::min(2.0 * light.outerConeAngle, 179.0 * kDegree);
        camera.projection = perspectiveOverBounds(scene, camera.eyeToWorld, fovy);
        break;
    }
    case engine::Light::Type::Directional: {
        camera.eyeToWorld = hasReported ? reported : lookAlong(center - placed.direction() * 2.0 * radius, placed.direction());
        const engine::Aabb box = boundsInEye(scene, camera.eyeToWorld);
        // Square, so the picture is not stretched; the depth range may start behind L.
        const glm::dvec2 mid = (glm::dvec2(box.min) + glm::dvec2(box.max)) * 0.5;
        const double half = std::max(box.max.x - box.min.x, box.max.y - box.min.y) * 0.5 * 1.01;
        const double margin = (box.max.z - box.min.z) * 0.01 + radius * 1e-6;
        camera.projection = glm::ortho(mid.x - half, mid.x + half, mid.y - half, mid.y + half,
                                       box.min.z - margin, box.max.z + margin);
        break;
    }
    case engine::Light::Type::Point: {
        const glm::dvec3 eye = placed.position();
        const glm::dvec3 toCenter = center - eye;
        const double distance = glm::length(toCenter);
        const bool inside = distance < radius;
        camera.eyeToWorld = lookAlong(eye, distance > radius * 1e-6 ? toCenter : placed.direction());
        const double fovy = inside ? 120.0 * kDegree
                                   : std::clamp(2.0 * std::asin(radius / distance), 40.0 * kDegree, 120.0 * kDegree);
        camera.projection = perspectiveOverBounds(scene, camera.eyeToWorld, fovy);
        break;
    }
    }
    return camera;
}

} // namespace engine_view
