#pragma once
// Scenes built in code for render tests: closed boxes (24 vertices, flat normals, welded
// edges by position), lights placed by position and target, a camera the same way.
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"
#include "engine/scene/Shapes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace engine::test {

// Rigid transform at `position` whose -Z looks at `target` (lights and cameras).
inline glm::dmat4 placeLooking(const glm::dvec3& position, const glm::dvec3& target) {
    const glm::dvec3 forward = glm::normalize(target - position);
    const glm::dvec3 up = std::abs(forward.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    return glm::inverse(glm::lookAt(position, target, up));
}

// A builder that keeps node/mesh bookkeeping out of the tests.
struct SceneBuilder {
    Scene scene;

    SceneBuilder() {
        Material grey;
        grey.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        grey.metallicFactor = 0.0f;
        scene.materials.push_back(grey);
        scene.sourcePath = "test-scene.gltf";
    }

    int addNode(Node node) {
        scene.nodes.push_back(std::move(node));
        const int index = static_cast<int>(scene.nodes.size()) - 1;
        scene.roots.push_back(index);
        return index;
    }

    // An axis-aligned closed box between min and max (world space).
    int addBox(const std::string& name, const glm::dvec3& min, const glm::dvec3& max) {
        scene.meshes.push_back(boxMesh(name, max - min));
        Node node;
        node.name = name;
        node.mesh = static_cast<int>(scene.meshes.size()) - 1;
        node.local = glm::translate(glm::dmat4(1.0), (min + max) * 0.5);
        return addNode(node);
    }

    int addLight(const std::string& name, Light::Type type, const glm::dvec3& position,
                 const glm::dvec3& target, nlohmann::json shadow = nlohmann::json::object(),
                 double outerCone = 0.7) {
        Light light;
        light.name = name;
        light.type = type;
        light.intensity = 10.0f;
        light.outerConeAngle = outerCone;
        light.innerConeAngle = outerCone * 0.5;
        if (!shadow.empty()) light.extras = {{"shadow", shadow}};
        scene.lights.push_back(light);
        Node node;
        node.name = name;
        node.light = static_cast<int>(scene.lights.size()) - 1;
        node.local = placeLooking(position, target);
        return addNode(node);
    }

    Scene build() {
        scene.updateWorldTransforms();
        return scene;
    }
};

inline FrameCamera cameraLooking(const glm::dvec3& eye, const glm::dvec3& target, int width,
                                 int height, double yfov = 0.9) {
    FrameCamera camera;
    camera.width = width;
    camera.height = height;
    camera.eyeToWorld = placeLooking(eye, target);
    camera.projection = glm::perspective(yfov, double(width) / height, 0.1, 100.0);
    return camera;
}

// World ray through the centre of pixel (x, y), y counted from the top (image order).
struct Ray {
    glm::dvec3 origin, direction;
};
inline Ray pixelRay(const FrameCamera& camera, int x, int y) {
    const glm::dvec2 ndc((x + 0.5) / camera.width * 2.0 - 1.0, 1.0 - (y + 0.5) / camera.height * 2.0);
    const glm::dmat4 inverse = glm::inverse(camera.projection * glm::inverse(camera.eyeToWorld));
    const glm::dvec4 a = inverse * glm::dvec4(ndc, -1.0, 1.0), b = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 from = glm::dvec3(a) / a.w, to = glm::dvec3(b) / b.w;
    return {from, glm::normalize(to - from)};
}

// Slab test: the ray parameter interval [t0, t1] inside the box, or false.
inline bool intersectBox(const glm::dvec3& origin, const glm::dvec3& direction, const Aabb& box,
                         double& t0, double& t1) {
    t0 = 0.0;
    t1 = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-300) {
            if (origin[axis] < box.min[axis] || origin[axis] > box.max[axis]) return false;
            continue;
        }
        double a = (box.min[axis] - origin[axis]) / direction[axis];
        double b = (box.max[axis] - origin[axis]) / direction[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

} // namespace engine::test
