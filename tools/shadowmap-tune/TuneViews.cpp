#include "TuneViews.h"

#include "engine/render/CameraSetup.h"
#include "engine/util/Error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace shadowmap_tune {

std::vector<engine::FrameCamera> tuneViews(const engine::Scene& scene, const ViewSpec& spec, int width, int height,
                                           const std::string& sceneFile) {
    std::vector<engine::FrameCamera> views;
    const bool cameras = spec.kind == ViewSpec::Kind::Cameras && (spec.given || !scene.cameraInstances.empty());
    if (cameras) {
        if (scene.cameraInstances.empty())
            engine::throwInputError(sceneFile, "--views cameras", "the scene has no camera (use --views orbit:N)");
        for (std::size_t i = 0; i < scene.cameraInstances.size(); ++i)
            views.push_back(engine::cameraFromScene(scene, static_cast<int>(i), width, height));
        return views;
    }
    // The framing camera's place (engine::framingCamera), turned around the vertical axis
    // through the scene's centre in N equal steps.
    const engine::FrameCamera framing = engine::framingCamera(scene, width, height);
    const glm::dvec3 eye = framing.position();
    const glm::dvec3 centre = scene.worldBounds.empty() ? glm::dvec3(0.0) : scene.worldBounds.center();
    const glm::dvec3 offset = eye - centre;
    for (int i = 0; i < spec.count; ++i) {
        const double angle = 2.0 * M_PI * i / spec.count;
        const glm::dvec3 turned(offset.x * std::cos(angle) - offset.z * std::sin(angle), offset.y,
                                offset.x * std::sin(angle) + offset.z * std::cos(angle));
        engine::FrameCamera view = framing;
        view.eyeToWorld = glm::inverse(glm::lookAt(centre + turned, centre, glm::dvec3(0.0, 1.0, 0.0)));
        views.push_back(view);
    }
    return views;
}

} // namespace shadowmap_tune
