#include "engine/scene/SceneEdit.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

glm::dmat4 orbitTransform(const glm::dmat4& transform, const glm::dvec3& center, double angle) {
    const glm::dmat4 rotation = glm::translate(glm::dmat4(1.0), center) *
                                glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0, 1, 0)) *
                                glm::translate(glm::dmat4(1.0), -center);
    return rotation * transform;
}

void orbitNode(Scene& scene, int node, const glm::dvec3& center, double angle) {
    Node& target = scene.nodes.at(node);
    const glm::dmat4 parentWorld =
        target.parent >= 0 ? scene.nodes[target.parent].world : glm::dmat4(1.0);
    // Orbit in world space, then express the result relative to the parent again.
    target.local = glm::inverse(parentWorld) * orbitTransform(target.world, center, angle);
    scene.updateWorldTransforms();
}

int addKeyLight(Scene& scene, Light::Type type, const std::string& name) {
    const Aabb bounds = scene.worldBounds.empty() ? Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)}
                                                  : scene.worldBounds;
    const glm::dvec3 center = bounds.center();
    const double radius = std::max(glm::length(bounds.extent()) * 0.5, 1e-6);
    const glm::dvec3 position = center + glm::normalize(glm::dvec3(0.6, 1.6, 0.9)) * (2.0 * radius);
    const double distance = glm::length(position - center);

    Light light;
    light.name = name;
    light.type = type;
    // Point/spot intensity is in candela (irradiance I/d^2); directional in lux.
    light.intensity = static_cast<float>(type == Light::Type::Directional ? 2.0 : 2.0 * distance * distance);
    light.outerConeAngle = std::min(std::asin(std::min(radius / distance, 1.0)) * 1.15, 1.5);
    light.innerConeAngle = light.outerConeAngle * 0.7;
    scene.lights.push_back(light);

    Node node;
    node.name = name;
    node.light = static_cast<int>(scene.lights.size()) - 1;
    const glm::dvec3 forward = glm::normalize(center - position);
    node.local = glm::inverse(glm::lookAt(position, center,
                                          std::abs(forward.y) > 0.99 ? glm::dvec3(0, 0, 1)
                                                                     : glm::dvec3(0, 1, 0)));
    scene.nodes.push_back(node);
    const int index = static_cast<int>(scene.nodes.size()) - 1;
    scene.roots.push_back(index);
    scene.updateWorldTransforms();
    return index;
}

} // namespace engine
