#pragma once
// Which mesh instances a camera sees, in the order to draw them: nearest first.
// Opaque surfaces drawn front to back let the depth test reject hidden fragments before
// they are shaded (llvmpipe tests depth ahead of the fragment shader, even one with an
// alpha-test discard, and skips blocks whose fragments all fail), so overdraw costs
// little. Measured on 2CylinderEngine at 1280x720: unshadowed frame 31.9 -> 27.8 ms,
// orbiting camera 31.9 -> 25.3 ms. No GL.
#include "engine/scene/Scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace engine {

struct DrawOrder {
    std::vector<int> instances;  // indices into Scene::meshInstances, nearest first
    int culled = 0;              // instances whose bounds miss the view frustum
};

// Instances whose world bounds touch the frustum of `viewProjection`, sorted by the
// distance from `eye` to the nearest point of their bounds (0 inside them); ties keep the
// scene's order, so the order (and with it every image) is deterministic.
DrawOrder nearestFirst(const Scene& scene, const glm::dmat4& viewProjection, const glm::dvec3& eye);

}  // namespace engine
