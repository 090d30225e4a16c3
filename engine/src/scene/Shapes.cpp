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

Primitive texturedQuadPrimitive(const glm::dvec2& min, const glm::dvec2& max, int material,
                                const glm::vec2& uvTopLeft, const glm::vec2& uvBottomRight) {
    Primitive primitive;
    const glm::vec2 lo(min), hi(max);
    // Counter-clockwise seen from +Z: bottom-left, bottom-right, top-right, top-left.
    primitive.positions = {{lo.x, lo.y, 0.0f}, {hi.x, lo.y, 0.0f}, {hi.x, hi.y, 0.0f}, {lo.x, hi.y, 0.0f}};
    primitive.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    primitive.texcoords = {{uvTopLeft.x, uvBottomRight.y}, {uvBottomRight.x, uvBottomRight.y},
                           {uvBottomRight.x, uvTopLeft.y}, {uvTopLeft.x, uvTopLeft.y}};
    primitive.indices = {0, 1, 2, 0, 2, 3};
    primitive.material = material;
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(glm::dvec3(p));
    return primitive;
}

void appendPrimitive(Primitive& to, const Primitive& from) {
    // An optional attribute survives only if every part carries it (an empty primitive
    // takes `from`'s).
    const bool first = to.positions.empty();
    const auto optional = [first](auto& into, const auto& part) {
        if (first || (!into.empty() && !part.empty())) into.insert(into.end(), part.begin(), part.end());
        else into.clear();
    };
    optional(to.texcoords, from.texcoords);
    optional(to.texcoords1, from.texcoords1);
    optional(to.colors, from.colors);
    optional(to.tangents, from.tangents);
    const auto base = static_cast<std::uint32_t>(to.positions.size());
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
    for (std::uint32_t index : from.indices) to.indices.push_back(base + index);
    for (const glm::vec3& p : from.positions) to.bounds.extend(glm::dvec3(p));
}

Image binaryAlphaImage(const std::string& name, int width, int height, const glm::u8vec3& rgb,
                       const std::function<bool(int column, int row)>& opaque) {
    Image image;
    image.name = name;
    image.width = width;
    image.height = height;
    image.rgba8.reserve(static_cast<std::size_t>(width) * height * 4);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column)
            image.rgba8.insert(image.rgba8.end(), {rgb.r, rgb.g, rgb.b, std::uint8_t(opaque(column, row) ? 255 : 0)});
    return image;
}

} // namespace engine
