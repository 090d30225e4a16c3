#include "engine/scene/DrawOrder.h"

#include "engine/scene/FrustumCull.h"

#include <algorithm>

namespace engine {

DrawOrder nearestFirst(const Scene& scene, const glm::dmat4& viewProjection, const glm::dvec3& eye) {
    DrawOrder order;
    std::vector<double> distance(scene.meshInstances.size(), 0.0);
    for (int index = 0; index < static_cast<int>(scene.meshInstances.size()); ++index) {
        const Aabb& bounds = scene.meshInstances[index].worldBounds;
        if (!boxIntersectsFrustum(viewProjection, bounds)) {
            ++order.culled;
            continue;
        }
        distance[index] = glm::length(glm::clamp(eye, bounds.min, bounds.max) - eye);
        order.instances.push_back(index);
    }
    std::stable_sort(order.instances.begin(), order.instances.end(),
                     [&](int a, int b) { return distance[a] < distance[b]; });
    return order;
}

}  // namespace engine
