#pragma once
// The side the tools look at a scene from when it brings no camera, shared by the framing
// camera (render/CameraSetup.h) and the key light placed relative to it (SceneEdit.h).
#include <glm/glm.hpp>

namespace engine {

// From the centre of the scene's bounds toward the framing camera's eye: above, to the side
// and in front (glTF's up is +Y, its front +Z).
inline glm::dvec3 framingViewDirection() { return glm::normalize(glm::dvec3(1.0, 0.8, 1.2)); }

} // namespace engine
