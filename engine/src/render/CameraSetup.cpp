#include "engine/render/CameraSetup.h"

#include "engine/scene/Framing.h"

#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

namespace {

// Near/far that bracket the scene's bounds as seen from the camera (eye looks down -Z).
glm::dvec2 depthRangeOfBounds(const Scene& scene, const glm::dmat4& eyeToWorld) {
    if (scene.worldBounds.empty()) return {0.1, 100.0};
    const glm::dmat4 view = glm::inverse(eyeToWorld);
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
    for (int i = 0; i < 8; ++i) {
        const double depth = -(view * glm::dvec4(scene.worldBounds.corner(i), 1.0)).z;
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    const double radius = glm::length(scene.worldBounds.extent()) * 0.5;
    farthest = std::max(farthest * 1.01, radius * 1e-3);
    return {std::max(nearest, farthest * 1e-4), farthest};
}

} // namespace

FrameCamera cameraFromScene(const Scene& scene, int instance, int width, int height) {
    const CameraInstance& placed = scene.cameraInstances.at(instance);
    const Camera& camera = scene.cameras.at(placed.camera);
    FrameCamera frame;
    frame.width = width;
    frame.height = height;
    // Drop any scale from the camera node: V must be a rigid transform.
    glm::dmat4 eyeToWorld = placed.world;
    for (int axis = 0; axis < 3; ++axis)
        eyeToWorld[axis] = glm::dvec4(glm::normalize(glm::dvec3(eyeToWorld[axis])), 0.0);
    frame.eyeToWorld = eyeToWorld;
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    if (camera.type == Camera::Type::Perspective) {
        double zfar = camera.zfar;
        if (zfar <= 0.0) zfar = std::max(depthRangeOfBounds(scene, eyeToWorld).y, camera.znear * 2.0);
        frame.projection = glm::perspective(camera.yfov, aspect, camera.znear, zfar);
    } else {
        frame.projection = glm::ortho(-camera.xmag, camera.xmag, -camera.ymag, camera.ymag,
                                      camera.znear, camera.zfar);
    }
    return frame;
}

int chooseCameraInstance(const Scene& scene, const std::string& name, const std::string& sceneFile) {
    if (name.empty()) return scene.cameraInstances.empty() ? -1 : 0;
    const int instance = findCameraInstanceByNameOrNumber(scene, name);
    if (instance < 0 && name == kFramingCameraName) return -1;
    if (instance < 0)
        throwInputError(sceneFile, "camera \"" + name + "\"", "no such camera (" + describeCameraInstances(scene) + ")");
    return instance;
}

FrameCamera chooseCamera(const Scene& scene, const std::string& name, int width, int height,
                         const std::string& sceneFile) {
    const int instance = chooseCameraInstance(scene, name, sceneFile);
    return instance < 0 ? framingCamera(scene, width, height)
                        : cameraFromScene(scene, instance, width, height);
}

FrameCamera framingCamera(const Scene& scene, int width, int height) {
    FrameCamera frame;
    frame.width = width;
    frame.height = height;
    const double yfov = 0.8;
    const Aabb bounds = scene.worldBounds.empty() ? Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)}
                                                  : scene.worldBounds;
    const double radius = std::max(glm::length(bounds.extent()) * 0.5, 1e-6);
    const glm::dvec3 target = bounds.center();
    const double distance = radius / std::sin(yfov * 0.5) * 1.05;
    const glm::dvec3 eye = target + framingViewDirection() * distance;
    frame.eyeToWorld = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0)));
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    frame.projection = glm::perspective(yfov, aspect, std::max(distance - radius, radius * 1e-3),
                                        distance + radius);
    return frame;
}

} // namespace engine
