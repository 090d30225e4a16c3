#include "engine/scene/Shapes.h"

namespace engine {

Primitive boxPrimitive(const glm::dvec3& size, int material) {
    const glm::vec3 half = glm::vec3(size * 0.5);
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    Primitive primitive;
    for (const glm::vec3& n : normals) {
        // Two axes spanning the face; (b, a) ordered so the corners run counter-clockwise
        // seen from outside: b x a = n.
        const glm::vec3 a = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        const glm::vec3 b = glm::cross(a, n);
        const auto base = static_cast<std::uint32_t>(primitive.positions.size());
        for (const glm::vec3& corner : {n - b - a, n + b - a, n + b + a, n - b + a}) {
            primitive.positions.push_back(corner * half);
            primitive.normals.push_back(n);
        }
        primitive.indices.insert(primitive.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    primitive.material = material;
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(glm::dvec3(p));
    return primitive;
}

Mesh boxMesh(const std::string& name, const glm::dvec3& size, int material) {
    Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(boxPrimitive(size, material));
    mesh.bounds = mesh.primitives[0].bounds;
    mesh.closed = true;
    return mesh;
}

} // namespace engine
