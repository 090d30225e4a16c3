// isClosedSurface decides whether the back-face shadow variant may use a mesh as caster;
// generateNormals fills primitives that come without normals.
#include "engine/scene/Scene.h"
#include "engine/scene/Shapes.h"

#include "gltf_test_support.h"

#include <gtest/gtest.h>

namespace {

using engine::Mesh;
using engine::Primitive;

Primitive primitiveFrom(const gltf_test::CubeGeometry& geometry) {
    Primitive primitive;
    for (std::size_t i = 0; i < geometry.positions.size(); i += 3)
        primitive.positions.emplace_back(geometry.positions[i], geometry.positions[i + 1], geometry.positions[i + 2]);
    primitive.indices = geometry.indices;
    return primitive;
}

Mesh meshOf(std::vector<Primitive> primitives) {
    Mesh mesh;
    mesh.primitives = std::move(primitives);
    return mesh;
}

TEST(MeshTopology, CubeWithSplitVerticesIsClosed) {
    const Primitive cube = primitiveFrom(gltf_test::splitVertexCube());
    ASSERT_EQ(cube.positions.size(), 24u);  // what an index-only check would call open
    EXPECT_TRUE(engine::isClosedSurface(meshOf({cube})));
}

TEST(MeshTopology, OpenBoxIsNotClosed) {
    Primitive box = primitiveFrom(gltf_test::splitVertexCube());
    box.indices.resize(box.indices.size() - 6);  // drop the last face
    EXPECT_FALSE(engine::isClosedSurface(meshOf({box})));
}

TEST(MeshTopology, CubeWithOneFlippedTriangleIsNotClosed) {
    Primitive cube = primitiveFrom(gltf_test::splitVertexCube());
    std::swap(cube.indices[1], cube.indices[2]);
    EXPECT_FALSE(engine::isClosedSurface(meshOf({cube})));
}

TEST(MeshTopology, TwoSeparateCubesInOneMeshAreClosed) {
    const Primitive left = primitiveFrom(gltf_test::splitVertexCube(-3, 0, 0));
    const Primitive right = primitiveFrom(gltf_test::splitVertexCube(3, 0, 0));
    EXPECT_TRUE(engine::isClosedSurface(meshOf({left, right})));
}

TEST(MeshTopology, VerticesAreWeldedAcrossPrimitives) {
    // One cube whose faces are split over two primitives (two materials, say).
    const Primitive cube = primitiveFrom(gltf_test::splitVertexCube());
    Primitive first = cube, second = cube;
    first.indices.assign(cube.indices.begin(), cube.indices.begin() + 18);
    second.indices.assign(cube.indices.begin() + 18, cube.indices.end());
    EXPECT_TRUE(engine::isClosedSurface(meshOf({first, second})));
}

TEST(MeshTopology, CubesTouchingAlongAnEdgeAreNotClosed) {
    // The shared edge is used by four triangles: not a manifold surface.
    const Primitive a = primitiveFrom(gltf_test::splitVertexCube(0, 0, 0));
    const Primitive b = primitiveFrom(gltf_test::splitVertexCube(2, 2, 0));
    EXPECT_FALSE(engine::isClosedSurface(meshOf({a, b})));
}

TEST(MeshTopology, DegenerateTrianglesAreIgnored) {
    Primitive cube = primitiveFrom(gltf_test::splitVertexCube());
    cube.indices.insert(cube.indices.end(), {0, 0, 1, 5, 5, 5});
    EXPECT_TRUE(engine::isClosedSurface(meshOf({cube})));
}

TEST(MeshTopology, NegativeZeroWeldsWithPositiveZero) {
    gltf_test::CubeGeometry geometry = gltf_test::splitVertexCube(0, 0, 0, 1);
    Primitive cube = primitiveFrom(geometry);
    // Move the whole cube so some coordinates become 0, then write one of them as -0.
    for (glm::vec3& p : cube.positions) p += glm::vec3(1.0f);
    for (glm::vec3& p : cube.positions)
        if (p.x == 0.0f) { p.x = -0.0f; break; }
    EXPECT_TRUE(engine::isClosedSurface(meshOf({cube})));
}

TEST(MeshTopology, EmptyMeshIsNotClosed) {
    EXPECT_FALSE(engine::isClosedSurface(Mesh{}));
}

TEST(MeshTopology, GeneratedNormalsOfAFlatQuadFaceItsWinding) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<glm::vec3> normals = engine::generateNormals(positions, {0, 1, 2, 0, 2, 3});
    ASSERT_EQ(normals.size(), 4u);
    for (const glm::vec3& n : normals) {
        EXPECT_NEAR(n.x, 0.0f, 1e-6f);
        EXPECT_NEAR(n.y, 0.0f, 1e-6f);
        EXPECT_NEAR(n.z, 1.0f, 1e-6f);
    }
}

TEST(MeshTopology, GeneratedNormalsAreAreaWeighted) {
    // Vertex 0 is shared by a big triangle facing +z (area 50) and a small one facing +x
    // (area 0.5): the normal leans 100:1 toward +z.
    const std::vector<glm::vec3> positions{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<glm::vec3> normals = engine::generateNormals(positions, {0, 1, 2, 0, 3, 4});
    const glm::vec3 expected = glm::normalize(glm::vec3(1.0f, 0.0f, 100.0f));
    EXPECT_NEAR(normals[0].x, expected.x, 1e-6f);
    EXPECT_NEAR(normals[0].z, expected.z, 1e-6f);
}

TEST(MeshTopology, VertexWithoutAreaGetsAUnitNormal) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
    const std::vector<glm::vec3> normals = engine::generateNormals(positions, {0, 1, 2});
    for (const glm::vec3& n : normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
}

} // namespace

TEST(Shapes, GeneratedBoxIsClosedAndWoundOutward) {
    const engine::Mesh box = engine::boxMesh("box", {2.0, 1.0, 0.5});
    EXPECT_TRUE(engine::isClosedSurface(box));
    const engine::Primitive& primitive = box.primitives[0];
    ASSERT_EQ(primitive.triangleCount(), 12u);
    for (std::size_t t = 0; t < primitive.indices.size(); t += 3) {
        const glm::vec3 a = primitive.positions[primitive.indices[t]];
        const glm::vec3 b = primitive.positions[primitive.indices[t + 1]];
        const glm::vec3 c = primitive.positions[primitive.indices[t + 2]];
        // Counter-clockwise from outside: the geometric normal points away from the centre.
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f), 0.0f) << "triangle " << t / 3;
    }
    EXPECT_EQ(box.bounds.max, glm::dvec3(1.0, 0.5, 0.25));
}

TEST(Shapes, TexturedQuadFacesPlusZWithGltfTexcoords) {
    const engine::Primitive quad = engine::texturedQuadPrimitive({-3.0, 0.0}, {3.0, 2.0}, 1);
    ASSERT_EQ(quad.triangleCount(), 2u);
    ASSERT_EQ(quad.texcoords.size(), 4u);
    EXPECT_EQ(quad.material, 1);
    for (std::size_t t = 0; t < quad.indices.size(); t += 3) {
        const glm::vec3 a = quad.positions[quad.indices[t]], b = quad.positions[quad.indices[t + 1]],
                        c = quad.positions[quad.indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t / 3;
    }
    for (std::size_t i = 0; i < 4; ++i) {
        // u grows with x; v = 0 on the top edge (the image's first row), 1 on the bottom.
        EXPECT_FLOAT_EQ(quad.texcoords[i].x, (quad.positions[i].x + 3.0f) / 6.0f);
        EXPECT_FLOAT_EQ(quad.texcoords[i].y, (2.0f - quad.positions[i].y) / 2.0f);
    }
    EXPECT_FALSE(engine::isClosedSurface(engine::Mesh{"quad", {quad}, false, quad.bounds}));
    EXPECT_EQ(quad.bounds.min, glm::dvec3(-3.0, 0.0, 0.0));
    EXPECT_EQ(quad.bounds.max, glm::dvec3(3.0, 2.0, 0.0));
}

TEST(Shapes, TexturedQuadMapsASubRectangleOfTheTexture) {
    const engine::Primitive quad = engine::texturedQuadPrimitive({0.0, 0.0}, {1.0, 1.0}, 0, {0.25f, 0.5f}, {0.5f, 1.0f});
    EXPECT_EQ(quad.texcoords[3], glm::vec2(0.25f, 0.5f));  // top-left corner (0, 1)
    EXPECT_EQ(quad.texcoords[1], glm::vec2(0.5f, 1.0f));   // bottom-right corner (1, 0)
}

TEST(Shapes, AppendedPrimitivesKeepTheirTrianglesAndSharedAttributes) {
    engine::Primitive both;
    engine::appendPrimitive(both, engine::texturedQuadPrimitive({0.0, 0.0}, {1.0, 1.0}));
    engine::appendPrimitive(both, engine::texturedQuadPrimitive({2.0, 0.0}, {3.0, 1.0}));
    ASSERT_EQ(both.positions.size(), 8u);
    EXPECT_EQ(both.texcoords.size(), 8u);
    EXPECT_EQ(both.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}));
    EXPECT_EQ(both.bounds.max, glm::dvec3(3.0, 1.0, 0.0));
    // A part without texcoords drops them for the whole (they would no longer line up).
    engine::appendPrimitive(both, engine::boxPrimitive({1.0, 1.0, 1.0}));
    EXPECT_TRUE(both.texcoords.empty());
    EXPECT_EQ(both.normals.size(), both.positions.size());
}

TEST(Shapes, BinaryAlphaImageIsRowMajorFromTheTop) {
    const engine::Image image = engine::binaryAlphaImage("mask", 3, 2, {10, 20, 30},
                                                         [](int column, int row) { return column == 2 && row == 0; });
    ASSERT_EQ(image.rgba8.size(), 3u * 2u * 4u);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(image.rgba8[4 * i], 10);
        EXPECT_EQ(image.rgba8[4 * i + 3], i == 2 ? 255 : 0) << "texel " << i;
    }
}
