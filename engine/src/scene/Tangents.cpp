#include "engine/scene/Tangents.h"

#include <cassert>
#include <cmath>
#include <optional>

namespace engine {

namespace {

// A triangle's directions in UV space: dp/du (the tangent) and -dp/dv (the bitangent,
// "up" in the image: Tangents.h says why the minus).
struct TriangleFrame {
    glm::dvec3 tangent;
    glm::dvec3 bitangent;
};

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Solves e1 = dp/du * d1.u + dp/dv * d1.v and e2 = dp/du * d2.u + dp/dv * d2.v for the
// triangle's edges e and UV edges d. Nothing when the UVs span no area (the system has no
// solution) or the result is not finite (UV spans so small that the division overflows).
std::optional<TriangleFrame> triangleFrame(const glm::dvec3 (&p)[3], const glm::dvec2 (&uv)[3]) {
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const glm::dvec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0.0) return std::nullopt;
    const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::dvec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
    if (!isFinite(dpdu) || !isFinite(dpdv)) return std::nullopt;
    return TriangleFrame{dpdu, -dpdv};
}

// The triangle's angle at corner `c` (0 for a corner with a zero-length edge).
double cornerAngle(const glm::dvec3 (&p)[3], int c) {
    const glm::dvec3 a = p[(c + 1) % 3] - p[c], b = p[(c + 2) % 3] - p[c];
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// `v` without its component along the unit `normal`.
glm::dvec3 inPlane(const glm::dvec3& v, const glm::dvec3& normal) { return v - normal * glm::dot(normal, v); }

// `v` scaled to unit length, or zero when it has none.
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : glm::dvec3(0.0);
}

// What the triangles around one vertex contribute, each direction taken in the plane of the
// vertex normal, normalized and weighted by the corner's angle (MikkTSpace's weighting: a
// vertex's frame does not depend on how finely the surface around it is cut).
struct VertexSums {
    glm::dvec3 tangent{0.0};
    glm::dvec3 bitangent{0.0};
    double weight = 0.0;  // the sum of the angles, the scale the sums are measured against
};

glm::dvec3 unitNormal(const glm::vec3& normal) {
    const glm::dvec3 n = unitOrZero(glm::dvec3(normal));
    return n == glm::dvec3(0.0) ? glm::dvec3(0.0, 0.0, 1.0) : n;  // as generateNormals' fallback
}

// The vertex's tangent from its sums: Gram-Schmidt against the normal (each contribution
// was in the plane already; this removes what rounding left), w from the side of
// cross(normal, tangent) the summed bitangent is on. A sum that (nearly) cancels, or is
// empty, says nothing reliable about the direction: any perpendicular, w = +1.
glm::vec4 finishTangent(const VertexSums& sums, const glm::dvec3& normal) {
    const glm::dvec3 tangent = inPlane(sums.tangent, normal);
    const double length = glm::length(tangent);
    // Each contribution is a unit vector times an angle: 1e-6 of their total is far above
    // rounding and far below any direction worth keeping.
    if (!(length > 1e-6 * sums.weight)) return glm::vec4(anyPerpendicular(glm::vec3(normal)), 1.0f);
    const glm::dvec3 unit = tangent / length;
    const float w = glm::dot(glm::cross(normal, unit), sums.bitangent) < 0.0 ? -1.0f : 1.0f;
    return glm::vec4(glm::vec3(unit), w);
}

} // namespace

glm::vec3 anyPerpendicular(const glm::vec3& normal) {
    const glm::dvec3 n = unitNormal(normal);
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return glm::vec3(glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x));
}

std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices) {
    assert(normals.size() == positions.size() && uvs.size() == positions.size());
    std::vector<glm::dvec3> unitNormals(normals.size());
    for (std::size_t v = 0; v < normals.size(); ++v) unitNormals[v] = unitNormal(normals[v]);

    std::vector<VertexSums> sums(positions.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t corner[3] = {indices[t], indices[t + 1], indices[t + 2]};
        glm::dvec3 p[3];
        glm::dvec2 uv[3];
        for (int c = 0; c < 3; ++c) {
            assert(corner[c] < positions.size());
            p[c] = glm::dvec3(positions[corner[c]]);
            uv[c] = glm::dvec2(uvs[corner[c]]);
        }
        const std::optional<TriangleFrame> frame = triangleFrame(p, uv);
        if (!frame) continue;
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3& n = unitNormals[corner[c]];
            const double angle = cornerAngle(p, c);
            VertexSums& sum = sums[corner[c]];
            sum.tangent += angle * unitOrZero(inPlane(frame->tangent, n));
            sum.bitangent += angle * unitOrZero(inPlane(frame->bitangent, n));
            sum.weight += angle;
        }
    }

    std::vector<glm::vec4> tangents(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) tangents[v] = finishTangent(sums[v], unitNormals[v]);
    return tangents;
}

} // namespace engine
