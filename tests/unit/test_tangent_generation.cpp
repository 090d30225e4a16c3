// generateTangents (Tangents.h) on meshes with known answers: the glTF orientation of the
// frame (tangent along increasing u, bitangent up the image = decreasing v) on planes with
// upright, mirrored and flipped UVs; MikkTSpace's corner-angle weighting; exact directions
// on a cylinder; unit tangents perpendicular to the normal on a curved, skewed mesh; and
// the fallback for UVs that span no area.
#include "engine/scene/Tangents.h"
#include "../support/TangentExpectations.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using engine::test::expectTangent;

namespace {

struct Mesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    std::vector<glm::vec4> tangents() const { return engine::generateTangents(positions, normals, uvs, indices); }
};

// The unit square in z = 0 facing +z (two triangles, counter-clockwise from +z) with the
// given UVs at (0,0), (1,0), (1,1), (0,1).
Mesh plane(const std::vector<glm::vec2>& uvs) {
    return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)), uvs,
            {0, 1, 2, 0, 2, 3}};
}

// Unit and perpendicular to the normal, to 1e-6; w exactly +-1.
void expectValidFrame(const glm::vec4& tangent, const glm::vec3& normal) {
    const glm::vec3 xyz(tangent);
    EXPECT_NEAR(glm::length(xyz), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(xyz, glm::normalize(normal)), 0.0f, 1e-6f);
    EXPECT_TRUE(tangent.w == 1.0f || tangent.w == -1.0f) << tangent.w;
}

} // namespace

// An image shown upright on the plane: u along +x, v along -y (glTF's v grows down the
// image). Tangent +x; the map's +Y (up the image) is +y = cross(+z, +x): w = +1.
TEST(TangentGeneration, UprightUvsGiveTangentAlongUAndWPlusOne) {
    const Mesh mesh = plane({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    for (const glm::vec4& tangent : mesh.tangents()) expectTangent(tangent, {1, 0, 0}, 1.0f);
}

// Mirrored left to right: u along -x. Tangent -x; up the image is still +y, but
// cross(+z, -x) = -y: w = -1.
TEST(TangentGeneration, MirroredUvsFlipW) {
    const Mesh mesh = plane({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
    for (const glm::vec4& tangent : mesh.tangents()) expectTangent(tangent, {-1, 0, 0}, -1.0f);
}

// UVs equal to x and y (the image upside down, as UVs written in OpenGL's convention show
// in glTF): up the image is now -y, opposite cross(+z, +x): w = -1. A generator following
// increasing v (MikkTSpace fed glTF's UVs unchanged) would answer +1 here.
TEST(TangentGeneration, UvsGrowingUpTheSurfaceGiveWMinusOne) {
    const Mesh mesh = plane({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    for (const glm::vec4& tangent : mesh.tangents()) expectTangent(tangent, {1, 0, 0}, -1.0f);
}

// Vertex 0 is shared by triangle A (corner angle 90 degrees, dp/du = +x) and triangle B
// (corner angle 45 degrees, dp/du = +y), of equal areas. Weighted by corner angle, as
// MikkTSpace does, its tangent is (pi/2 x + pi/4 y) normalized = (2, 1, 0) / sqrt 5; by area
// it would be (1, 1, 0) / sqrt 2.
TEST(TangentGeneration, ContributionsAreWeightedByCornerAngle) {
    Mesh mesh;
    // A = (0, 1, 2) with u = x, v = -y; B = (0, 3, 4) with u = y, v = x. Both map the image
    // without mirroring it and agree at vertex 0: uv (0, 0).
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {1, -1, 0}};
    mesh.normals.assign(5, glm::vec3(0, 0, 1));
    mesh.uvs = {{0, 0}, {1, 0}, {0, -1}, {-1, 0}, {-1, 1}};
    mesh.indices = {0, 1, 2, 0, 3, 4};
    const std::vector<glm::vec4> tangents = mesh.tangents();
    ASSERT_EQ(tangents.size(), 5u);
    // Bitangents (decreasing v): A's +y, B's -x; their weighted sum (-pi/4, pi/2) lies on the
    // side of cross(+z, t) = (-1, 2, 0) / sqrt 5: w = +1.
    expectTangent(tangents[0], glm::vec3(2, 1, 0) / std::sqrt(5.0f), 1.0f);
    expectTangent(tangents[1], {1, 0, 0}, 1.0f, "A alone: bitangent +y = cross(+z, +x)");
    expectTangent(tangents[4], {0, 1, 0}, 1.0f, "B alone: bitangent -x = cross(+z, +y)");
}

// A cylinder of radius 1 about y with smooth normals, u around it and v growing with y.
// Every chord's dp/du, projected into the tangent plane, is the circle's direction at the
// vertex: tangent (-sin a, 0, cos a) exactly (to float), at seams and inside alike. Up the
// image (decreasing v) is -y = cross(n, t): w = +1.
TEST(TangentGeneration, CylinderTangentsFollowTheCircleExactly) {
    Mesh mesh;
    const int columns = 12, rows = 3;
    for (int row = 0; row <= rows; ++row)
        for (int column = 0; column <= columns; ++column) {
            // A quarter turn, cut into uneven columns.
            const double a = 0.5 * column / columns * 3.141592653589793;
            const double angle = a + 0.05 * std::sin(7.0 * a);
            mesh.positions.emplace_back(std::cos(angle), row * 0.5, std::sin(angle));
            mesh.normals.emplace_back(std::cos(angle), 0.0, std::sin(angle));
            mesh.uvs.emplace_back(angle, row * 0.25);
        }
    const auto at = [&](int row, int column) { return static_cast<std::uint32_t>(row * (columns + 1) + column); };
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column)
            mesh.indices.insert(mesh.indices.end(), {at(row, column), at(row + 1, column), at(row + 1, column + 1),
                                                     at(row, column), at(row + 1, column + 1), at(row, column + 1)});
    const std::vector<glm::vec4> tangents = mesh.tangents();
    ASSERT_EQ(tangents.size(), mesh.positions.size());
    for (std::size_t v = 0; v < tangents.size(); ++v) {
        const glm::vec3& n = mesh.normals[v];
        expectTangent(tangents[v], {-n.z, 0, n.x}, 1.0f, ("vertex " + std::to_string(v)).c_str());
    }
}

// A bumpy, skewed height field with analytic normals and UVs that shear and stretch: no
// tangent has a known direction, but every one is unit and perpendicular to its normal.
TEST(TangentGeneration, TangentsAreUnitAndPerpendicularToTheNormal) {
    Mesh mesh;
    const int n = 9;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = 0.3 * i + 0.05 * j, y = 0.25 * j;
            const double z = 0.4 * std::sin(2.0 * x) * std::cos(3.0 * y);
            const double dzdx = 0.8 * std::cos(2.0 * x) * std::cos(3.0 * y);
            const double dzdy = -1.2 * std::sin(2.0 * x) * std::sin(3.0 * y);
            mesh.positions.emplace_back(x, y, z);
            mesh.normals.emplace_back(glm::normalize(glm::dvec3(-dzdx, -dzdy, 1.0)));
            mesh.uvs.emplace_back(x + 0.3 * y * y, 0.7 * y - 0.2 * x);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<std::uint32_t>(j * (n + 1) + i);
            mesh.indices.insert(mesh.indices.end(), {v, v + 1, v + n + 2, v, v + n + 2, v + n + 1});
        }
    const std::vector<glm::vec4> tangents = mesh.tangents();
    ASSERT_EQ(tangents.size(), mesh.positions.size());
    for (std::size_t v = 0; v < tangents.size(); ++v) {
        SCOPED_TRACE("vertex " + std::to_string(v));
        expectValidFrame(tangents[v], mesh.normals[v]);
    }
}

// Every vertex at the same UV: no triangle has a frame. Each vertex still gets a unit
// tangent perpendicular to its normal, w = +1.
TEST(TangentGeneration, DegenerateUvsGiveAUnitPerpendicularTangent) {
    Mesh mesh = plane(std::vector<glm::vec2>(4, glm::vec2(0.5f)));
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
    mesh.normals[2] = tilted;  // not an axis, so the fallback is not trivially +x
    const std::vector<glm::vec4> tangents = mesh.tangents();
    ASSERT_EQ(tangents.size(), 4u);
    for (std::size_t v = 0; v < 4; ++v) {
        SCOPED_TRACE("vertex " + std::to_string(v));
        expectValidFrame(tangents[v], mesh.normals[v]);
        EXPECT_EQ(tangents[v].w, 1.0f);
    }
}

// UVs collinear on one triangle only: the vertex that only that triangle touches falls back;
// the others keep the frame of the triangle whose UVs span an area.
TEST(TangentGeneration, ATriangleWithoutUvAreaContributesNothing) {
    Mesh mesh = plane({{0, 1}, {1, 1}, {1, 0}, {0.5f, 0.5f}});  // (0,1), (1,0), (0.5,0.5): one line
    const std::vector<glm::vec4> tangents = mesh.tangents();
    ASSERT_EQ(tangents.size(), 4u);
    for (const std::size_t v : {0u, 1u, 2u}) expectTangent(tangents[v], {1, 0, 0}, 1.0f);
    expectValidFrame(tangents[3], mesh.normals[3]);
}

TEST(TangentGeneration, AnyPerpendicularIsUnitAndPerpendicular) {
    for (const glm::vec3& normal : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, -3, 0),
                                    glm::vec3(0.2f, -0.9f, -0.1f), glm::vec3(0, 0, 0)}) {
        const glm::vec3 t = engine::anyPerpendicular(normal);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(t, normal), 0.0f, 1e-6f);
    }
    EXPECT_EQ(engine::anyPerpendicular(glm::vec3(0, 0, 1)), glm::vec3(1, 0, 0));
    EXPECT_EQ(engine::anyPerpendicular(glm::vec3(0, 0, 0)), glm::vec3(1, 0, 0)) << "a zero normal counts as +z";
}
