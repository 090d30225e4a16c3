#pragma once
// The viewer's camera: a glTF camera (or the framing one) exactly as engine-render places it,
// until the mouse moves it; from then on an orbit about a target (yaw, pitch, distance) that
// starts where the glTF camera was. Orbit, pan and zoom take pixel deltas and wheel steps.
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <string>

namespace engine_view {

class OrbitCamera {
public:
    // `name`: a glTF camera by name (empty: the first glTF camera, else the framing one).
    // Throws InputError (naming `sceneFile`) when there is no such camera.
    OrbitCamera(const engine::Scene& scene, const std::string& sceneFile, const std::string& name);

    // Back to glTF camera `instance` (index into scene.cameraInstances) or, with -1, the
    // framing camera. Returns false (and changes nothing) when there is no such camera.
    bool select(int instance);
    bool selectByName(const std::string& name);  // a glTF camera by name
    int selected() const { return instance_; }
    bool moved() const { return moved_; }
    std::string describe() const;  // e.g. "main_camera", "main_camera (orbit)", "framing"

    void orbit(double dxPixels, double dyPixels);
    void pan(double dxPixels, double dyPixels, int viewportHeight);
    void zoom(double wheelSteps);  // > 0: closer

    // V and P_eye for a width x height image. Unmoved: cameraFromScene / framingCamera,
    // bit for bit what engine-render uses for the same camera and size.
    engine::FrameCamera frameCamera(int width, int height) const;

private:
    void startOrbit();  // takes yaw/pitch/target from the selected camera's placement
    glm::dvec3 eye() const;

    const engine::Scene& scene_;
    int instance_ = -1;  // -1: framing camera
    bool moved_ = false;
    glm::dvec3 target_{0.0};
    double distance_ = 1.0, yaw_ = 0.0, pitch_ = 0.0;
    double fovy_ = 0.8;          // perspective
    bool orthographic_ = false;
    double ymag_ = 1.0;          // orthographic half height
};

} // namespace engine_view
