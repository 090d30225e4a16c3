#include "engine/scene/SceneEdit.h"

#include "engine/scene/Framing.h"

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

glm::dvec3 keyLightDirection(const KeyLightAngles& angles) {
    const glm::dvec3 view = framingViewDirection();
    const glm::dvec3 toward = glm::normalize(glm::dvec3(view.x, 0.0, view.z));  // the camera's side
    const glm::dvec3 right(toward.z, 0.0, -toward.x);  // the camera's right, looking at the centre
    const double azimuth = glm::radians(angles.azimuthDegrees), elevation = glm::radians(angles.elevationDegrees);
    const glm::dvec3 horizontal = std::cos(azimuth) * toward + std::sin(azimuth) * right;
    return std::cos(elevation) * horizontal + std::sin(elevation) * glm::dvec3(0.0, 1.0, 0.0);
}

int addKeyLight(Scene& scene, Light::Type type, const std::string& name, KeyLightAngles angles) {
    const Aabb bounds = scene.worldBounds.empty() ? Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)}
                                                  : scene.worldBounds;
    const glm::dvec3 center = bounds.center();
    const double radius = std::max(glm::length(bounds.extent()) * 0.5, 1e-6);
    const glm::dvec3 position = center + keyLightDirection(angles) * (2.0 * radius);
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

int addGround(Scene& scene, const std::string& name) {
    const Aabb bounds = scene.worldBounds.empty() ? Aabb{glm::dvec3(-1.0), glm::dvec3(1.0)}
                                                  : scene.worldBounds;
    const glm::dvec3 center = bounds.center();
    const double radius = std::max(glm::length(bounds.extent()) * 0.5, 1e-6);
    // 1e-3 radii below the lowest point: the model's underside does not z-fight with the
    // ground, and the gap (0.1% of the model's size) is far below a texel of any map that
    // covers the model, so its contact shadow still touches it.
    const glm::dvec3 origin(center.x, bounds.min.y - 1e-3 * radius, center.z);
    const float half = static_cast<float>(2.0 * radius);

    Material material;
    material.name = name;
    material.baseColorFactor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    material.metallicFactor = 0.0f;
    material.roughnessFactor = 0.9f;
    scene.materials.push_back(material);

    // Positions relative to the node (placed at `origin` in double): the float vertices stay
    // small even for a model far from the world origin.
    Primitive quad;
    quad.positions = {{-half, 0.0f, -half}, {half, 0.0f, -half}, {half, 0.0f, half}, {-half, 0.0f, half}};
    quad.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    quad.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above (+Y)
    quad.material = static_cast<int>(scene.materials.size()) - 1;
    quad.castShadows = false;  // a receiver only: it shadows nothing and stays out of the maps
    for (const glm::vec3& p : quad.positions) quad.bounds.extend(glm::dvec3(p));
    Mesh mesh;
    mesh.name = name;
    mesh.bounds = quad.bounds;
    mesh.primitives.push_back(std::move(quad));
    mesh.closed = false;
    scene.meshes.push_back(std::move(mesh));

    Node node;
    node.name = name;
    node.mesh = static_cast<int>(scene.meshes.size()) - 1;
    node.castShadows = false;
    node.local = glm::translate(glm::dmat4(1.0), origin);
    scene.nodes.push_back(node);
    const int index = static_cast<int>(scene.nodes.size()) - 1;
    scene.roots.push_back(index);
    scene.updateWorldTransforms();
    return index;
}

} // namespace engine
