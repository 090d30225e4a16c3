#pragma once
// The scene of the truth tests, built in code so every expected answer is a formula:
// a 10x10 plane at y = 0, a closed 2x2x2 box floating at y = 1..3 over its centre, one light
// above, and a camera looking down at it from the side. Everything can be moved by `offset`
// (the truth must hold 10^6 from the origin as it does at the origin).
#include "engine/render/Frame.h"
#include "engine/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

namespace truth::test {

constexpr int kPlaneInstance = 0;  // index into Scene::meshInstances
constexpr int kBoxInstance = 1;
constexpr double kLightHeight = 8.0;
// Directional light: shines along (kSlope, -1, 0), so its shadow is the box swept along x.
constexpr double kSlope = 0.3;

inline engine::Primitive finishPrimitive(engine::Primitive primitive) {
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(glm::dvec3(p));
    return primitive;
}

// A quad per face (vertices not shared, so normals stay flat), wound counter-clockwise seen
// from outside: (-u-v, u-v, u+v, -u+v) around the outward normal n = u x v.
inline engine::Mesh makeBox(const glm::vec3& center, float halfSize) {
    engine::Primitive box;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0.0f) std::swap(u, v);
            const auto base = static_cast<std::uint32_t>(box.positions.size());
            for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1),
                                     glm::vec2(-1, 1)}) {
                box.positions.push_back(center + halfSize * (n + corner.x * u + corner.y * v));
                box.normals.push_back(n);
            }
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) box.indices.push_back(base + i);
        }
    engine::Mesh mesh;
    mesh.name = "box";
    mesh.primitives.push_back(finishPrimitive(std::move(box)));
    mesh.bounds = mesh.primitives[0].bounds;
    mesh.closed = engine::isClosedSurface(mesh);
    return mesh;
}

// The rectangle x in [x0, x1], z in [z0, z1] of the horizontal plane at height y, facing +y.
inline engine::Mesh makeHorizontalRectangle(const std::string& name, float x0, float x1, float z0,
                                            float z1, float y = 0.0f) {
    engine::Primitive rectangle;
    rectangle.positions = {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}};
    rectangle.normals.assign(4, glm::vec3(0, 1, 0));
    rectangle.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +y
    engine::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(finishPrimitive(std::move(rectangle)));
    mesh.bounds = mesh.primitives[0].bounds;
    return mesh;
}

inline engine::Mesh makePlane(float halfSize) {
    return makeHorizontalRectangle("plane", -halfSize, halfSize, -halfSize, halfSize);
}

// L (light -> world) for a light at `position` shining along `direction` (lights shine
// down their -Z): the inverse of a view matrix looking that way.
inline glm::dmat4 lightToWorld(const glm::dvec3& position, const glm::dvec3& direction) {
    const glm::dvec3 up = std::abs(direction.y) > 0.9 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    return glm::inverse(glm::lookAt(position, position + direction, up));
}

inline engine::Scene boxOverPlane(engine::Light::Type type, const glm::dvec3& offset = {}) {
    engine::Scene scene;
    scene.meshes = {makePlane(5.0f), makeBox({0.0f, 2.0f, 0.0f}, 1.0f)};
    engine::Light light;
    light.name = "key";
    light.type = type;
    light.outerConeAngle = 0.7;  // covers the plane out to radius 6.7 at distance 8
    light.innerConeAngle = 0.5;
    scene.lights = {light};

    const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), offset);
    engine::Node plane, box, lamp;
    plane.name = "plane";
    plane.mesh = 0;
    plane.local = moved;
    box.name = "box";
    box.mesh = 1;
    box.local = moved;
    lamp.name = "key";
    lamp.light = 0;
    const glm::dvec3 direction = type == engine::Light::Type::Directional
                                     ? glm::normalize(glm::dvec3(kSlope, -1.0, 0.0))
                                     : glm::dvec3(0.0, -1.0, 0.0);
    lamp.local = moved * lightToWorld({0.0, kLightHeight, 0.0}, direction);
    scene.nodes = {plane, box, lamp};
    scene.roots = {0, 1, 2};
    scene.updateWorldTransforms();
    return scene;
}

// Looking down at the box from the front-right, at 45 degrees or so.
inline engine::FrameCamera sideCamera(int width, int height, const glm::dvec3& offset = {}) {
    engine::FrameCamera camera;
    const glm::dvec3 eye = offset + glm::dvec3(2.0, 8.0, 9.0);
    camera.eyeToWorld = glm::inverse(glm::lookAt(eye, offset, glm::dvec3(0.0, 1.0, 0.0)));
    camera.projection = glm::perspective(0.8, double(width) / height, 0.1, 100.0);
    camera.width = width;
    camera.height = height;
    return camera;
}

} // namespace truth::test
