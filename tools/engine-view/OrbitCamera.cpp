#include "OrbitCamera.h"

#include "engine/render/CameraSetup.h"
#include "engine/scene/SceneNames.h"
#include "engine/util/Error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine_view {

namespace {

constexpr double kRadiansPerPixel = 0.005;
constexpr double kZoomPerStep = 0.9;
constexpr double kMaxPitch = 1.55;  // just short of straight up/down: lookAt needs an up

double sceneRadius(const engine::Scene& scene) {
    return scene.worldBounds.empty() ? 1.0 : std::max(glm::length(scene.worldBounds.extent()) * 0.5, 1e-6);
}

glm::dvec3 sceneCenter(const engine::Scene& scene) {
    return scene.worldBounds.empty() ? glm::dvec3(0.0) : scene.worldBounds.center();
}

} // namespace

OrbitCamera::OrbitCamera(const engine::Scene& scene, const std::string& sceneFile, const std::string& name)
    : scene_(scene) {
    if (!name.empty()) {
        instance_ = engine::findCameraInstanceByNameOrNumber(scene, name);
        if (instance_ < 0)
            engine::throwInputError(sceneFile, "camera \"" + name + "\"",
                                    "no such camera (" + engine::describeCameraInstances(scene) + ")");
    } else {
        instance_ = scene.cameraInstances.empty() ? -1 : 0;
    }
}

bool OrbitCamera::select(int instance) {
    if (instance < -1 || instance >= static_cast<int>(scene_.cameraInstances.size())) return false;
    instance_ = instance;
    moved_ = false;
    return true;
}

bool OrbitCamera::selectByName(const std::string& name) {
    const int instance = scene_.findCameraInstance(name);
    return instance >= 0 && select(instance);
}

std::string OrbitCamera::describe() const {
    std::string name = engine::kFramingCameraName;
    if (instance_ >= 0) {
        const engine::CameraInstance& placed = scene_.cameraInstances[instance_];
        name = scene_.cameras[placed.camera].name;
        if (name.empty()) name = scene_.nodes[placed.node].name;
        if (name.empty()) name = "camera " + std::to_string(instance_ + 1);
    }
    return moved_ ? name + " (orbit)" : name;
}

void OrbitCamera::startOrbit() {
    if (moved_) return;
    const engine::FrameCamera base = frameCamera(16, 16);  // the size does not matter here
    orthographic_ = base.projection[3][3] == 1.0;
    if (orthographic_) ymag_ = 1.0 / base.projection[1][1];
    else fovy_ = 2.0 * std::atan(1.0 / base.projection[1][1]);
    const glm::dvec3 eye = base.position();
    const glm::dvec3 forward = -glm::normalize(glm::dvec3(base.eyeToWorld[2]));
    // The target: the point along the view axis nearest the scene's centre (what the camera
    // looks at), at least a tenth of the scene's radius ahead.
    distance_ = std::max(glm::dot(sceneCenter(scene_) - eye, forward), sceneRadius(scene_) * 0.1);
    target_ = eye + forward * distance_;
    const glm::dvec3 back = -forward;
    pitch_ = std::asin(std::clamp(back.y, -1.0, 1.0));
    pitch_ = std::clamp(pitch_, -kMaxPitch, kMaxPitch);
    yaw_ = std::atan2(back.x, back.z);
    moved_ = true;
}

glm::dvec3 OrbitCamera::eye() const {
    const glm::dvec3 back(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_));
    return target_ + back * distance_;
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
    startOrbit();
    yaw_ -= dxPixels * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ + dyPixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dxPixels, double dyPixels, int viewportHeight) {
    startOrbit();
    // World units per pixel at the target's depth, so the target follows the cursor.
    const double halfHeight = orthographic_ ? ymag_ : distance_ * std::tan(fovy_ * 0.5);
    const double perPixel = 2.0 * halfHeight / std::max(viewportHeight, 1);
    const glm::dmat4 view = glm::lookAt(eye(), target_, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::dvec3 up(view[0][1], view[1][1], view[2][1]);
    target_ += (-dxPixels * right + dyPixels * up) * perPixel;
}

void OrbitCamera::zoom(double wheelSteps) {
    startOrbit();
    const double scale = std::pow(kZoomPerStep, wheelSteps);
    if (orthographic_) ymag_ *= scale;
    else distance_ = std::max(distance_ * scale, sceneRadius(scene_) * 1e-4);
}

engine::FrameCamera OrbitCamera::frameCamera(int width, int height) const {
    if (!moved_)
        return instance_ >= 0 ? engine::cameraFromScene(scene_, instance_, width, height)
                              : engine::framingCamera(scene_, width, height);
    engine::FrameCamera camera;
    camera.width = width;
    camera.height = height;
    const glm::dvec3 position = eye();
    camera.eyeToWorld = glm::inverse(glm::lookAt(position, target_, glm::dvec3(0.0, 1.0, 0.0)));
    // Near and far bracket the scene's bounds as seen from here (as the framing camera does).
    const double radius = sceneRadius(scene_);
    const double toCenter = glm::length(sceneCenter(scene_) - position);
    const double far = toCenter + radius * 1.01;
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    if (orthographic_) {
        camera.projection = glm::ortho(-ymag_ * aspect, ymag_ * aspect, -ymag_, ymag_,
                                       std::max(toCenter - radius * 1.01, 0.0), far);
    } else {
        camera.projection = glm::perspective(fovy_, aspect, std::max(toCenter - radius, far * 1e-4), far);
    }
    return camera;
}

} // namespace engine_view
