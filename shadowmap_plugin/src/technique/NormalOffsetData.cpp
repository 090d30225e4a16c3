#include "technique/NormalOffsetData.h"

#include <algorithm>
#include <cmath>

namespace shadowmap {

float texelWidthPerDepth(const LightView& view, int resolution) {
    if (view.warped) return static_cast<float>(2.0 / (std::abs(view.warpFitScale.x) * resolution));
    const double scale = std::min(std::abs(view.projection[0][0]), std::abs(view.projection[1][1]));
    return static_cast<float>(2.0 / (scale * resolution));
}

float texelWidthPerDepthSquared(const LightView& view, int resolution) {
    if (!view.warped) return 0.0f;
    const double n = view.nearPlane, f = view.farPlane;
    return static_cast<float>((f - n) / (std::abs(view.warpFitScale.y) * f * n * resolution));
}

glm::vec4 lightInEye(const LightView& view, engine::Light::Type type, const glm::dmat4& worldToEye) {
    // The light looks down its -z axis: toward it is +z; a positional light sits at L's origin.
    if (type == engine::Light::Type::Directional)
        return glm::vec4(glm::vec3(glm::normalize(glm::dvec3(worldToEye * view.lightToWorld[2]))), 0.0f);
    return glm::vec4(glm::vec3(worldToEye * view.lightToWorld[3]), 1.0f);
}

} // namespace shadowmap
