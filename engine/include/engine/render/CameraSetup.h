#pragma once
// Turns a glTF camera (or none) into the frame's V and P_eye, in double.
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

namespace engine {

// The camera placed by scene.cameraInstances[instance]. The projection uses the viewport's
// aspect ratio (a stored glTF aspectRatio would stretch the image on other sizes); an
// infinite far plane (zfar absent) is fitted to the scene's bounds so depth keeps precision.
FrameCamera cameraFromScene(const Scene& scene, int instance, int width, int height);

// What the tools call the framing camera (--camera framing, engine-view's camera list).
inline constexpr const char* kFramingCameraName = "framing";

// A camera that frames the whole scene from above and to the side, for scenes without one.
FrameCamera framingCamera(const Scene& scene, int width, int height);

// The tools' rule: the glTF camera `name` means (its name, its node's, or its number:
// findCameraInstanceByNameOrNumber; an InputError naming `sceneFile` and listing the
// scene's cameras if none), else the scene's first camera, else the framing camera.
// "framing" asks for the framing camera even when the scene has cameras (as engine-view's
// 0 key does), unless one of them is called so.
FrameCamera chooseCamera(const Scene& scene, const std::string& name, int width, int height,
                         const std::string& sceneFile);

// The scene.cameraInstances index chooseCamera takes, -1 for the framing camera: a tool
// that poses an animation re-reads it (cameraFromScene) to follow an animated camera.
int chooseCameraInstance(const Scene& scene, const std::string& name, const std::string& sceneFile);

} // namespace engine
