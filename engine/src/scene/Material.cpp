#include "engine/scene/Scene.h"

#include <cmath>

namespace engine {

glm::mat3 UvTransform::matrix() const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    // Columns: T * R * S, with R's first column (cos, -sin) and second (sin, cos).
    return glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f), glm::vec3(s * scale.y, c * scale.y, 0.0f),
                     glm::vec3(offset, 1.0f));
}

float shadowAlphaCutoff(const Material& material) {
    switch (material.alphaMode) {
    case AlphaMode::Opaque: return -1.0f;
    case AlphaMode::Mask: return material.alphaCutoff > 0.0f ? material.alphaCutoff : -1.0f;
    case AlphaMode::Blend: return material.blendShadowCutoff > 0.0f ? material.blendShadowCutoff : -1.0f;
    }
    return -1.0f;
}

} // namespace engine
