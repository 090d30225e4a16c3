#include "technique/SoftShadowLayers.h"

#include <algorithm>
#include <cmath>

namespace shadowmap {

namespace {

// 0 stands for an infinite far plane (GLSL has no infinity to pass).
float finiteOrZero(double far) { return std::isinf(far) ? 0.0f : static_cast<float>(far); }

bool perspective(const LightState& light) { return light.type != engine::Light::Type::Directional; }

} // namespace

glm::vec4 softLayer(const LightView& view, const LightState& light) {
    const double size = light.settings.lightSize(light.type);
    // The depth terms always: the moments lookups (vsm, evsm) read them too.
    const glm::vec2 depthTerms = perspective(light)
                                     ? glm::vec2(static_cast<float>(view.nearPlane), finiteOrZero(view.farPlane))
                                     : glm::vec2(0.0f, static_cast<float>(view.farPlane - view.nearPlane));
    if (!(size > 0.0)) return glm::vec4(0.0f, 0.0f, depthTerms);
    // Map coordinates per unit of tangent (perspective) or of world distance (orthographic):
    // the projection's x and y scale, halved by the scale-bias to [0, 1]. A perspective
    // light's edge spreads by its radius per unit of (d_receiver - d_blocker) / (d_receiver
    // d_blocker); an orthographic one's by tan(angular_diameter / 2) per unit of depth.
    const double spread = perspective(light) ? size : std::tan(0.5 * size);
    const glm::vec2 scale(static_cast<float>(0.5 * view.projection[0][0] * spread),
                          static_cast<float>(0.5 * view.projection[1][1] * spread));
    return glm::vec4(scale, depthTerms);
}

glm::vec4 softCubeLayer(const PointLightViews& views, const LightState& light) {
    // The lookup offsets directions on the face's plane at unit distance: tangent units (0
    // for a light without a size; the depth terms always, as softLayer's).
    const float radius = static_cast<float>(std::max(light.settings.lightSize(light.type), 0.0));
    return glm::vec4(radius, radius, static_cast<float>(views.nearPlane), finiteOrZero(views.farPlane));
}

} // namespace shadowmap
