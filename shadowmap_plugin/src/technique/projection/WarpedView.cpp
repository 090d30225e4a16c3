#include "technique/projection/WarpedView.h"

#include "technique/UnseenShadows.h"

#include "math/CascadeFit.h"

namespace shadowmap {

LightView fitWarpedView(const LightState& light, const PlanContext& context, const FrustumFitOptions& options,
                        std::optional<glm::dvec2> slice, LispsmFit* chosen) {
    glm::dvec3 direction;
    if (std::string why = directionProblem(context.scene.lightInstances[light.slot], direction); !why.empty())
        return invalidView("directional " + why);
    const engine::FrameCamera& camera = context.camera;
    WarpEye eye;
    eye.position = camera.position();
    eye.direction = glm::normalize(-glm::dvec3(camera.eyeToWorld[2]));
    double nearDepth = 0.0, farDepth = 0.0;
    std::vector<glm::dvec3> body;
    if (receiverDepthRange({camera.eyeToWorld, camera.projection}, context.bounds.receivers, nearDepth, farDepth)) {
        eye.nearDepth = slice ? std::max(slice->x, nearDepth) : nearDepth;
        body = visibleReceiverPoints(context.bounds.receivers, camera, slice);
    }
    const double scale = light.settings.lispsmNScale * (slice ? kSliceWarpNScale : 1.0);
    return fitLispsm(direction, eye, body, context.bounds.casters, options, scale, chosen);
}

} // namespace shadowmap
