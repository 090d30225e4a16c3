#include "CameraPath.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace evaluation {

std::vector<engine::FrameCamera> onePixelPan(const engine::FrameCamera& camera, int frames) {
    // P00 maps eye x / -z (perspective) or eye x (orthographic) to NDC: 2 / width per pixel.
    const double pixel = 2.0 / (camera.projection[0][0] * camera.width);
    const bool perspective = camera.projection[2][3] != 0.0;
    const glm::dmat4 step = perspective ? glm::rotate(glm::dmat4(1.0), std::atan(pixel), glm::dvec3(0, 1, 0))
                                        : glm::translate(glm::dmat4(1.0), glm::dvec3(pixel, 0, 0));
    std::vector<engine::FrameCamera> path(frames > 0 ? frames : 0, camera);
    for (int frame = 1; frame < frames; ++frame) path[frame].eyeToWorld = path[frame - 1].eyeToWorld * step;
    return path;
}

} // namespace evaluation
