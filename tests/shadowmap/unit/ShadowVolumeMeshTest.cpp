// Shadow volumes built on the CPU (math/ShadowVolumeMesh.h): welding and adjacency, the
// silhouette and cap counts, and above all that the emitted triangles bound exactly the
// shadowed region. That is checked by the generalized winding number of the emitted surface
// (the sum of its triangles' signed solid angles over 4 pi) at random points, against a ray
// cast to the light through the mesh: the winding must be an integer, equal to the number of
// triangles the ray crosses (those facing the light for the classic volume of a closed mesh),
// so non-zero exactly where the point is in shadow.
#include "math/ShadowVolumeMesh.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using shadowmap::ShadowVolumeBound;
using shadowmap::ShadowVolumeCounts;
using shadowmap::ShadowVolumeMesh;
using shadowmap::VolumeCaps;

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

// A cube as a glTF exporter writes it: 4 vertices per face (split by normal), 24 in all, 2
// triangles per face, counter-clockwise seen from outside. Corners are center + half * (+-1):
// exact in float for the integers used here, so the faces' copies of a corner weld.
Mesh splitCube(const glm::vec3& center, float half) {
    Mesh mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (side < 0.0f) std::swap(u, v);  // keeps cross(u, v) == n: counter-clockwise outside
            const auto first = std::uint32_t(mesh.positions.size());
            for (const glm::vec2& c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                mesh.positions.push_back(center + half * (n + c.x * u + c.y * v));
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
        }
    return mesh;
}

// The same mesh with every triangle wound the other way (a room seen from inside).
Mesh inwardWound(Mesh mesh) {
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    return mesh;
}

Mesh joined(const Mesh& a, const Mesh& b) {
    Mesh mesh = a;
    const auto offset = std::uint32_t(a.positions.size());
    mesh.positions.insert(mesh.positions.end(), b.positions.begin(), b.positions.end());
    for (std::uint32_t i : b.indices) mesh.indices.push_back(offset + i);
    return mesh;
}

// The cube without the 2 triangles of its +z face (the face written first for axis 2).
Mesh openBox() {
    Mesh mesh = splitCube(glm::vec3(0.0f), 1.0f);
    mesh.indices.erase(mesh.indices.begin() + 24, mesh.indices.begin() + 30);
    return mesh;
}

// A square in z = 0, counter-clockwise seen from +z.
Mesh quadSheet() {
    return {{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 1, 2, 0, 2, 3}};
}

// Three fins around the z axis sharing the edge (0, 0, -1) - (0, 0, 1): non-manifold.
Mesh threeFins() {
    Mesh mesh{{{0, 0, -1}, {0, 0, 1}}, {}};
    for (int k = 0; k < 3; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / 3.0 + 0.3;
        mesh.positions.push_back(glm::vec3(float(std::cos(angle)), float(std::sin(angle)), 0.2f * k));
        mesh.indices.insert(mesh.indices.end(), {0u, 1u, std::uint32_t(2 + k)});
    }
    return mesh;
}

// A UV sphere as exporters write it: a seam column duplicated and a row of `slices` copies of
// each pole, so welding must merge them and drop the triangles that collapse at the poles.
// Counter-clockwise outside: (row i, i + 1) runs south, column j east, south x east = outward.
Mesh uvSphere(int slices, int stacks, float radius, const glm::dvec3& center = glm::dvec3(0.0)) {
    Mesh mesh;
    for (int i = 0; i <= stacks; ++i) {
        const double theta = std::numbers::pi * i / stacks;
        const bool pole = i == 0 || i == stacks;
        const double ring = pole ? 0.0 : std::sin(theta), z = pole ? (i == 0 ? 1.0 : -1.0) : std::cos(theta);
        for (int j = 0; j <= slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * (j % slices) / slices;
            mesh.positions.push_back(glm::vec3(center + double(radius) * glm::dvec3(ring * std::cos(phi),
                                                                                   ring * std::sin(phi), z)));
        }
    }
    const auto row = std::uint32_t(slices + 1);
    for (std::uint32_t i = 0; i < std::uint32_t(stacks); ++i)
        for (std::uint32_t j = 0; j < std::uint32_t(slices); ++j) {
            const std::uint32_t v00 = i * row + j, v01 = v00 + 1, v10 = v00 + row, v11 = v10 + 1;
            mesh.indices.insert(mesh.indices.end(), {v00, v10, v11, v00, v11, v01});
        }
    return mesh;
}

ShadowVolumeMesh build(const Mesh& mesh) { return ShadowVolumeMesh(mesh.positions, mesh.indices); }

// ---- The reference: which triangles a ray from a point to the light crosses ----

glm::dvec3 corner(const Mesh& mesh, std::size_t i) { return glm::dvec3(mesh.positions[mesh.indices[i]]); }

// Möller-Trumbore: whether origin + s * dir, 0 < s < maxS, passes through triangle (a, b, c).
bool crosses(const glm::dvec3& origin, const glm::dvec3& dir, double maxS, const glm::dvec3& a, const glm::dvec3& b,
             const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return false;  // parallel to the plane, or a degenerate triangle
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = glm::dot(e2, q) / det;
    return t > 0.0 && t < maxS;
}

struct Crossings {
    int all = 0;     // triangles the ray to the light crosses
    int facing = 0;  // of those, the ones facing the light
    bool operator==(const Crossings&) const = default;
};

// light: (position, 1) or (direction toward the light, 0), in the mesh's space.
Crossings crossingsToLight(const Mesh& mesh, const glm::dvec4& light, const glm::dvec3& q) {
    const bool directional = light.w == 0.0;
    const glm::dvec3 dir = directional ? glm::dvec3(light) : glm::dvec3(light) - q;
    const double maxS = directional ? std::numeric_limits<double>::infinity() : 1.0;
    Crossings crossings;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::dvec3 a = corner(mesh, i), b = corner(mesh, i + 1), c = corner(mesh, i + 2);
        if (!crosses(q, dir, maxS, a, b, c)) continue;
        ++crossings.all;
        const glm::dvec3 toLight = directional ? glm::dvec3(light) : glm::dvec3(light) - a;
        crossings.facing += glm::dot(glm::cross(b - a, c - a), toLight) > 0.0;
    }
    return crossings;
}

// Points within this distance of a boundary of the shadow are skipped: the reference ray
// runs on the mesh in double, the volume's vertices are rounded to float (relative 6e-8, so
// about 1e-6 at the distances used here), and the two may disagree that close to a boundary.
// 1e-3 leaves a wide margin. A point is skipped when the crossings differ at any of its 14
// neighbours at the 6 axis and 8 diagonal offsets of this size: the boundary is a closed
// surface made of caps and quads far wider than that, so one passing that close puts some of
// them on its other side.
constexpr double kBoundaryMargin = 1e-3;

bool nearShadowBoundary(const Mesh& mesh, const glm::dvec4& light, const glm::dvec3& q, const Crossings& atQ) {
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                const int nonZero = (dx != 0) + (dy != 0) + (dz != 0);
                if (nonZero != 1 && nonZero != 3) continue;
                const glm::dvec3 offset = kBoundaryMargin * glm::dvec3(dx, dy, dz);
                if (!(crossingsToLight(mesh, light, q + offset) == atQ)) return true;
            }
    return false;
}

// ---- The generalized winding number of the emitted volume ----

// The direction of an emitted vertex seen from q: toward the point, or the point at
// infinity's own direction (w = 0).
glm::dvec3 directionFrom(const glm::vec4& v, const glm::dvec3& q) {
    const glm::dvec3 d = v.w == 0.0f ? glm::dvec3(v) : glm::dvec3(v) / double(v.w) - q;
    return glm::normalize(d);
}

// Sum of the triangles' signed solid angles seen from q, over 4 pi (Van Oosterom & Strackee,
// 1983: tan(omega / 2) = a.(b x c) / (1 + a.b + a.c + b.c) for unit a, b, c). A triangle
// counter-clockwise seen from outside counts positive from inside, so a closed surface wound
// that way has winding +1 inside and 0 outside.
double windingNumber(const std::vector<glm::vec4>& triangles, const glm::dvec3& q) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 2 < triangles.size(); i += 3) {
        const glm::dvec3 a = directionFrom(triangles[i], q), b = directionFrom(triangles[i + 1], q),
                         c = directionFrom(triangles[i + 2], q);
        const double numerator = glm::dot(a, glm::cross(b, c));
        const double denominator = 1.0 + glm::dot(a, b) + glm::dot(a, c) + glm::dot(b, c);
        sum += 2.0 * std::atan2(numerator, denominator);
    }
    return sum / (4.0 * std::numbers::pi);
}

using VertexKey = std::array<std::uint32_t, 4>;

VertexKey keyOf(const glm::vec4& v) {
    return {std::bit_cast<std::uint32_t>(v.x), std::bit_cast<std::uint32_t>(v.y), std::bit_cast<std::uint32_t>(v.z),
            std::bit_cast<std::uint32_t>(v.w)};
}

// Every directed edge of the emitted triangles (vertices compared bit for bit) is matched by
// the same edge traversed the other way: the surface is closed and consistently wound. An edge
// from a vertex to itself bounds nothing and is not counted.
bool closedSurface(const std::vector<glm::vec4>& triangles) {
    std::map<std::pair<VertexKey, VertexKey>, int> balance;
    for (std::size_t i = 0; i + 2 < triangles.size(); i += 3)
        for (int k = 0; k < 3; ++k) {
            const VertexKey from = keyOf(triangles[i + k]), to = keyOf(triangles[i + (k + 1) % 3]);
            if (from < to)
                ++balance[{from, to}];
            else if (to < from)
                --balance[{to, from}];
        }
    for (const auto& [edge, count] : balance)
        if (count != 0) return false;
    return true;
}

// A triangle with two equal corners: what a directional light's far cap and half of each of its
// side quads would be, which are not to be emitted.
bool anyDegenerate(const std::vector<glm::vec4>& triangles) {
    for (std::size_t i = 0; i + 2 < triangles.size(); i += 3) {
        const VertexKey a = keyOf(triangles[i]), b = keyOf(triangles[i + 1]), c = keyOf(triangles[i + 2]);
        if (a == b || b == c || c == a) return true;
    }
    return false;
}

// What the random points of one check saw.
struct VolumeCheck {
    int kept = 0;      // points not near a shadow boundary
    int shadowed = 0;  // of those, in shadow
    int maxCount = 0;  // the largest winding number met
    int litInShadow = 0;  // in shadow but counted 0, inside a part turned inside out (see InsideOut)
    int outsideBound = 0;  // points not checked: outside the bound the volume was made for
};

// Whether a posed volume may read lit in shadow where the posed surface is turned inside out.
enum class InsideOut { Fails, Allowed };

// Half the points are uniform in a cube around `center`; the other half lie on the ray from
// the light through a random point of a random triangle, from a little before the triangle to
// a few units past it, so that thin shadows and the region just behind the caster are met.
struct Sampling {
    glm::dvec3 center{0.0};
    double halfSize = 4.0;
    int points = 600;
    unsigned seed = 1;
};

glm::dvec3 samplePoint(const Mesh& mesh, const glm::dvec4& light, const Sampling& sampling, int i,
                       std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (i % 2 == 0) {
        const glm::dvec3 offset(unit(random), unit(random), unit(random));
        return sampling.center + sampling.halfSize * (2.0 * offset - 1.0);
    }
    const std::size_t triangle = std::uniform_int_distribution<std::size_t>(0, mesh.indices.size() / 3 - 1)(random);
    double u = unit(random), v = unit(random);
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    const glm::dvec3 a = corner(mesh, 3 * triangle), b = corner(mesh, 3 * triangle + 1),
                     c = corner(mesh, 3 * triangle + 2);
    const glm::dvec3 p = a + u * (b - a) + v * (c - a);
    const glm::dvec3 away = glm::normalize(light.w == 0.0 ? -glm::dvec3(light) : p - glm::dvec3(light));
    return p + (4.0 * unit(random) - 1.0) * away;
}

// The winding may differ from an integer only by the rounding of a sum of a few hundred solid
// angles in double (each within about 1e-15 of its value away from the surface): 1e-6 is
// far above that and far below the 1 that separates two counts.
constexpr double kIntegerTolerance = 1e-6;

// Checks `triangles`, the volume of `mesh` in target space (classic: the classic volume of a
// closed outward mesh, else the summed per-triangle volumes), at random points q of the mesh's
// space (see Sampling): its winding at toTarget * q is the count of crossings the reference
// expects there: every triangle crossed for the summed per-triangle volumes, the crossings of
// facing triangles for the classic one. The sign follows toTarget's orientation (a mirror turns
// the volume inside out in target space). With InsideOut::Allowed a point in shadow may count 0
// (tallied in litInShadow) where the mesh's own winding number is negative, and only there.
// With a bound (radius > 0) only the points strictly inside it in target space are checked; the
// others are tallied in outsideBound.
VolumeCheck checkTriangles(const Mesh& mesh, bool classic, const std::vector<glm::vec4>& triangles,
                           const glm::dvec4& light, const Sampling& sampling, const glm::dmat4& toTarget,
                           InsideOut insideOut = InsideOut::Fails, const ShadowVolumeBound& bound = {}) {
    EXPECT_TRUE(closedSurface(triangles));
    EXPECT_FALSE(anyDegenerate(triangles));
    const int orientation = glm::determinant(glm::dmat3(toTarget)) < 0.0 ? -1 : 1;
    std::vector<glm::vec4> surface;  // the mesh itself, for its winding number
    for (std::uint32_t i : mesh.indices) surface.push_back(glm::vec4(mesh.positions[i], 1.0f));

    std::mt19937 random(sampling.seed);
    VolumeCheck check;
    for (int i = 0; i < sampling.points; ++i) {
        const glm::dvec3 q = samplePoint(mesh, light, sampling, i, random);
        const glm::dvec3 qInTarget = glm::dvec3(toTarget * glm::dvec4(q, 1.0));
        if (bound.radius > 0.0 && glm::distance(qInTarget, bound.center) >= bound.radius) {
            ++check.outsideBound;
            continue;
        }
        const Crossings crossings = crossingsToLight(mesh, light, q);
        if (nearShadowBoundary(mesh, light, q, crossings)) continue;
        ++check.kept;
        const int count = classic ? crossings.facing : crossings.all;
        const double winding = windingNumber(triangles, qInTarget);
        const long rounded = std::lround(winding);
        // The last condition is what the stencil test reads: non-zero exactly where something is
        // between q and the light. The first failing point is enough to report.
        const bool integer = std::abs(winding - double(rounded)) <= kIntegerTolerance;
        const bool litInShadow = rounded == 0 && crossings.all > 0;
        const bool insideOutHere = insideOut == InsideOut::Allowed && litInShadow && windingNumber(surface, q) < -0.5;
        if (!integer || rounded != orientation * count || ((rounded != 0) != (crossings.all > 0) && !insideOutHere)) {
            ADD_FAILURE() << "at (" << q.x << ", " << q.y << ", " << q.z << "): winding " << winding << ", expected "
                          << orientation * count << " (crossings: " << crossings.all << ", facing the light: "
                          << crossings.facing << ")";
            return check;
        }
        check.litInShadow += insideOutHere;
        check.shadowed += crossings.all > 0;
        check.maxCount = std::max(check.maxCount, int(std::abs(rounded)));
    }
    return check;
}

// Builds the mesh's volume (for the bound, if any) and checks it (checkTriangles).
VolumeCheck checkVolume(const Mesh& mesh, const glm::dvec4& light, const Sampling& sampling = {},
                        const glm::dmat4& toTarget = glm::dmat4(1.0), const ShadowVolumeBound& bound = {}) {
    const ShadowVolumeMesh volumeMesh = build(mesh);
    std::vector<glm::vec4> triangles;
    volumeMesh.appendVolume(light, toTarget, triangles, bound);
    return checkTriangles(mesh, volumeMesh.closedOutward(), triangles, light, sampling, toTarget, InsideOut::Fails,
                          bound);
}

// The mesh built at rest, its volume emitted posed (every copy of a welded vertex posed to the
// same place, so `posed` with rest's indices is the posed geometry), checked against the posed
// geometry.
VolumeCheck checkPosedVolume(const Mesh& rest, const std::vector<glm::vec3>& posed, const glm::dvec4& light,
                             const Sampling& sampling = {}, InsideOut insideOut = InsideOut::Fails) {
    const ShadowVolumeMesh volumeMesh = build(rest);
    std::vector<glm::vec4> triangles;
    volumeMesh.appendVolume(light, glm::dmat4(1.0), posed, triangles);
    return checkTriangles(Mesh{posed, rest.indices}, volumeMesh.closedOutward(), triangles, light, sampling,
                          glm::dmat4(1.0), insideOut);
}

// A check means something only if most points were kept and both lit and shadowed ones met.
// Points outside a bound do not count (checkTriangles).
void expectMeaningful(const VolumeCheck& check, const Sampling& sampling = {}) {
    EXPECT_GT(check.kept, (sampling.points - check.outsideBound) * 9 / 10);
    EXPECT_GT(check.shadowed, check.kept / 20);
    EXPECT_LT(check.shadowed, check.kept - check.kept / 20);
}

struct NamedLight {
    std::string name;
    glm::dvec4 light;
};

glm::dvec4 pointLight(double x, double y, double z) { return {x, y, z, 1.0}; }
glm::dvec4 towardLight(double x, double y, double z) { return {x, y, z, 0.0}; }

// The lights every closed or open mesh around the origin (within about 1.05) is checked with.
std::vector<NamedLight> standardLights() {
    return {{"point outside", pointLight(3.0, 2.2, 2.6)},
            {"point above", pointLight(0.15, -0.1, 4.0)},
            {"directional diagonal", towardLight(1.0, 0.8, 1.2)},
            {"directional from below", towardLight(-0.2, 0.3, -1.0)},
            {"point close to a face", pointLight(0.1, 0.2, 1.08)}};
}

// ---- Welding and adjacency ----

TEST(ShadowVolumeMeshTest, SplitCubeWeldsIntoClosedMesh) {
    const ShadowVolumeMesh cube = build(splitCube(glm::vec3(0.0f), 1.0f));
    EXPECT_TRUE(cube.closed());
    EXPECT_TRUE(cube.closedOutward());
    EXPECT_EQ(cube.vertexCount(), 8u);
    EXPECT_EQ(cube.triangleCount(), 12u);
    EXPECT_EQ(cube.edgeCount(), 18u);  // 12 cube edges + 6 face diagonals
}

TEST(ShadowVolumeMeshTest, MissingTriangleOpensMesh) {
    Mesh mesh = splitCube(glm::vec3(0.0f), 1.0f);
    mesh.indices.resize(mesh.indices.size() - 3);
    const ShadowVolumeMesh cube = build(mesh);
    EXPECT_FALSE(cube.closed());
    EXPECT_FALSE(cube.closedOutward());
    EXPECT_EQ(cube.triangleCount(), 11u);
    EXPECT_EQ(cube.edgeCount(), 18u);
}

TEST(ShadowVolumeMeshTest, QuadSheetIsOpen) {
    const ShadowVolumeMesh sheet = build(quadSheet());
    EXPECT_FALSE(sheet.closed());
    EXPECT_EQ(sheet.triangleCount(), 2u);
    EXPECT_EQ(sheet.edgeCount(), 5u);
}

TEST(ShadowVolumeMeshTest, NonManifoldEdgeIsNotClosed) {
    const ShadowVolumeMesh fins = build(threeFins());
    EXPECT_FALSE(fins.closed());
    EXPECT_EQ(fins.edgeCount(), 7u);  // the shared edge + 2 of each fin's own
}

TEST(ShadowVolumeMeshTest, InwardWoundClosedMeshIsClosedButNotOutward) {
    const ShadowVolumeMesh room = build(inwardWound(splitCube(glm::vec3(0.0f), 1.0f)));
    EXPECT_TRUE(room.closed());
    EXPECT_FALSE(room.closedOutward());
    // Two closed outward pieces (even overlapping ones) are closed and outward.
    const ShadowVolumeMesh pair =
        build(joined(splitCube(glm::vec3(0.0f), 1.0f), splitCube(glm::vec3(1.0f, 0.0f, 0.0f), 2.0f)));
    EXPECT_TRUE(pair.closed());
    EXPECT_TRUE(pair.closedOutward());
    // One piece wound inward is enough to lose the classic volume.
    const ShadowVolumeMesh hollow =
        build(joined(splitCube(glm::vec3(0.0f), 2.0f), inwardWound(splitCube(glm::vec3(0.0f), 1.0f))));
    EXPECT_TRUE(hollow.closed());
    EXPECT_FALSE(hollow.closedOutward());
}

TEST(ShadowVolumeMeshTest, SphereWeldsSeamAndPolesAndDropsCollapsedTriangles) {
    const int slices = 16, stacks = 10;
    const ShadowVolumeMesh sphere = build(uvSphere(slices, stacks, 1.0f));
    EXPECT_TRUE(sphere.closed());
    EXPECT_TRUE(sphere.closedOutward());
    EXPECT_EQ(sphere.vertexCount(), std::size_t(slices * (stacks - 1) + 2));
    EXPECT_EQ(sphere.triangleCount(), std::size_t(2 * slices * (stacks - 1)));  // one per pole quad dropped
}

TEST(ShadowVolumeMeshTest, WeldsExactPositionsOnly) {
    const float nearOne = std::nextafter(1.0f, 2.0f);
    // Corner 3 is corner 1 with -0 for +0 (equal, welded); corner 4 is one float step away.
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, -0.0f, 0}, {nearOne, 0, 0}};
    const ShadowVolumeMesh welded(positions, {0, 1, 2, 0, 2, 3});
    EXPECT_EQ(welded.vertexCount(), 3u);
    EXPECT_TRUE(welded.closed());  // the same triangle back to back
    const ShadowVolumeMesh apart(positions, {0, 1, 2, 0, 2, 4});
    EXPECT_EQ(apart.vertexCount(), 4u);
    EXPECT_FALSE(apart.closed());
    // A triangle with two corners at one position (distinct input vertices) is dropped.
    const ShadowVolumeMesh degenerate(positions, {0, 1, 3, 0, 1, 2});
    EXPECT_EQ(degenerate.triangleCount(), 1u);
}

TEST(ShadowVolumeMeshTest, RejectsBadInput) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(ShadowVolumeMesh(positions, {0, 1}), std::invalid_argument);
    EXPECT_THROW(ShadowVolumeMesh(positions, {0, 1, 3}), std::invalid_argument);
    const std::vector<glm::vec3> withNan{{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
    EXPECT_THROW(ShadowVolumeMesh(withNan, {0, 1, 2}), std::invalid_argument);
    EXPECT_NO_THROW((void)ShadowVolumeMesh(withNan, {0, 1, 0}));  // a position no triangle uses is not looked at
    const ShadowVolumeMesh empty;
    std::vector<glm::vec4> out;
    EXPECT_EQ(empty.appendVolume(pointLight(0, 0, 1), glm::dmat4(1.0), out).capTriangles, 0u);
    EXPECT_TRUE(out.empty());
}

// ---- Counts ----

// Triangles per side quad: 2, or 1 for a directional light without a bound (the other is
// degenerate).
std::size_t emittedVertices(const ShadowVolumeCounts& counts, bool oneTrianglePerQuad) {
    return 3 * (counts.capTriangles + counts.silhouetteEdges * (oneTrianglePerQuad ? 1 : 2));
}

TEST(ShadowVolumeMeshTest, CubeCountsFromDiagonalAndAbove) {
    const ShadowVolumeMesh cube = build(splitCube(glm::vec3(0.0f), 1.0f));
    struct Case {
        std::string name;
        glm::dvec4 light;
        std::uint64_t silhouette, caps;
    };
    // Along a diagonal 3 faces (6 triangles) face the light and the silhouette is a hexagon;
    // from straight above the top faces it and the sides are edge-on, near caps like the top
    // (ShadowVolumeMesh.cpp, kEdgeOnSine), so the silhouette is the bottom's square. A point
    // light adds the far cap: the other triangles.
    const Case cases[] = {{"directional diagonal", towardLight(1, 1, 1), 6, 6},
                          {"directional above", towardLight(0, 0, 1), 4, 10},
                          {"point diagonal", pointLight(5, 5, 5), 6, 12},
                          {"point above", pointLight(0, 0, 10), 4, 12}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        std::vector<glm::vec4> out(1, glm::vec4(7.0f));  // appended after what is there
        const ShadowVolumeCounts counts = cube.appendVolume(c.light, glm::dmat4(1.0), out);
        EXPECT_EQ(counts.silhouetteEdges, c.silhouette);
        EXPECT_EQ(counts.capTriangles, c.caps);
        EXPECT_EQ(out.size(), 1 + emittedVertices(counts, c.light.w == 0.0));
        EXPECT_EQ(out[0], glm::vec4(7.0f));
    }
}

// For z-pass a closed mesh's volume is its side quads alone: the same quads, vertex for vertex,
// as with caps, and no cap. An open sheet (summed per-triangle volumes) keeps its caps: it can
// be seen through from behind, so its caps may lie in front of a surface.
TEST(ShadowVolumeMeshTest, CapsLeftOutOnlyForClosedMeshes) {
    const ShadowVolumeMesh cube = build(splitCube(glm::vec3(0.0f), 1.0f));
    const ShadowVolumeMesh sheet = build(quadSheet());
    for (const glm::dvec4& light : {pointLight(5, 5, 5), towardLight(1, 1, 1), pointLight(0, 0, 10)}) {
        std::vector<glm::vec4> withCaps, without;
        const ShadowVolumeCounts full = cube.appendVolume(light, glm::dmat4(1.0), withCaps);
        const ShadowVolumeCounts sides = cube.appendVolume(light, glm::dmat4(1.0), without, {}, VolumeCaps::LeftOutIfClosed);
        EXPECT_EQ(sides.capTriangles, 0u);
        EXPECT_EQ(sides.silhouetteEdges, full.silhouetteEdges);
        ASSERT_EQ(without.size(), withCaps.size() - 3 * full.capTriangles);
        // The caps come first in the output, the quads after them.
        EXPECT_TRUE(std::equal(without.begin(), without.end(), withCaps.end() - without.size()));

        std::vector<glm::vec4> sheetWith, sheetWithout;
        const ShadowVolumeCounts sheetFull = sheet.appendVolume(light, glm::dmat4(1.0), sheetWith);
        const ShadowVolumeCounts sheetKept =
            sheet.appendVolume(light, glm::dmat4(1.0), sheetWithout, {}, VolumeCaps::LeftOutIfClosed);
        EXPECT_GT(sheetFull.capTriangles, 0u);
        EXPECT_EQ(sheetKept.capTriangles, sheetFull.capTriangles);
        EXPECT_EQ(sheetWithout, sheetWith);
    }
}

TEST(ShadowVolumeMeshTest, BoundedDirectionalLightEmitsFarCapAndWholeQuads) {
    // With a bound a directional light's extruded vertices are distinct points: the far cap (the
    // triangles not facing the light) and both halves of each side quad are emitted. A point
    // light's counts do not change.
    const ShadowVolumeMesh cube = build(splitCube(glm::vec3(0.0f), 1.0f));
    const ShadowVolumeBound bound{glm::dvec3(0.5, -0.2, 0.1), 4.0};
    struct Case {
        std::string name;
        glm::dvec4 light;
        std::uint64_t silhouette, caps;
    };
    const Case cases[] = {{"directional diagonal", towardLight(1, 1, 1), 6, 12},
                          {"directional above", towardLight(0, 0, 1), 4, 12},
                          {"point diagonal", pointLight(5, 5, 5), 6, 12}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        std::vector<glm::vec4> out;
        const ShadowVolumeCounts counts = cube.appendVolume(c.light, glm::dmat4(1.0), out, bound);
        EXPECT_EQ(counts.silhouetteEdges, c.silhouette);
        EXPECT_EQ(counts.capTriangles, c.caps);
        EXPECT_EQ(out.size(), emittedVertices(counts, false));
    }
}

TEST(ShadowVolumeMeshTest, SummedVolumeCountsFoldAsMultiplicityTwo) {
    // Two triangles folded along the edge (0,0,0)-(0,1,0) into a shallow V, consistently wound
    // (both fronts face down and outward), lit from low on the +x side so that one faces the
    // light and the other does not: turned to face it, both run the fold the same way, so the
    // fold carries 2 quads, plus 1 on each of the 4 outer edges.
    const Mesh fold{{{0, 0, 0}, {0, 1, 0}, {1, 0, 0.2f}, {-1, 0, 0.2f}}, {0, 1, 2, 1, 0, 3}};
    const ShadowVolumeMesh folded = build(fold);
    ASSERT_FALSE(folded.closed());
    std::vector<glm::vec4> out;
    const ShadowVolumeCounts counts = folded.appendVolume(pointLight(3.0, 0.4, -0.3), glm::dmat4(1.0), out);
    EXPECT_EQ(counts.silhouetteEdges, 6u);
    EXPECT_EQ(counts.capTriangles, 4u);  // both near caps, both far caps
    EXPECT_EQ(out.size(), emittedVertices(counts, false));
    // Lit from below, which both fronts face, the fold cancels.
    out.clear();
    EXPECT_EQ(folded.appendVolume(pointLight(0.0, 0.4, -3.0), glm::dmat4(1.0), out).silhouetteEdges, 4u);
    expectMeaningful(checkVolume(fold, pointLight(3.0, 0.4, -0.3), {.halfSize = 3.0}));
}

// ---- The volume bounds the shadow (winding numbers) ----

TEST(ShadowVolumeMeshTest, ClosedCubeVolumeIsOneInShadowZeroInLight) {
    const Mesh cube = splitCube(glm::vec3(0.0f), 1.0f);
    for (const NamedLight& light : standardLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkVolume(cube, light.light);
        expectMeaningful(check);
        // Convex and wound outward: +1 in shadow, never more, never negative. The stencil ops
        // (z-fail: back faces increment) are set up for this sign.
        EXPECT_EQ(check.maxCount, 1);
    }
}

TEST(ShadowVolumeMeshTest, ClosedSphereVolumeIsOneInShadowZeroInLight) {
    const Mesh sphere = uvSphere(16, 10, 1.0f);
    for (const NamedLight& light : standardLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkVolume(sphere, light.light, {.points = 400, .seed = 2});
        expectMeaningful(check, {.points = 400});
        EXPECT_EQ(check.maxCount, 1);
    }
}

TEST(ShadowVolumeMeshTest, IntersectingCubesCountEachEntry) {
    // Two closed cubes in one mesh overlap; a ray from the light can enter both, so the classic
    // volume counts 2 there: still non-zero, as the stencil test needs.
    const Mesh pair = joined(splitCube(glm::vec3(0.0f), 1.0f), splitCube(glm::vec3(1.0f, 0.0f, 0.0f), 1.0f));
    ASSERT_TRUE(build(pair).closedOutward());
    for (const NamedLight& light : standardLights()) {
        SCOPED_TRACE(light.name);
        expectMeaningful(checkVolume(pair, light.light, {.seed = 3}));
    }
    const VolumeCheck alongX = checkVolume(pair, pointLight(5.0, 0.2, 0.1), {.seed = 4});
    expectMeaningful(alongX);
    EXPECT_EQ(alongX.maxCount, 2);
}

std::vector<NamedLight> sheetLights() {
    return {{"point above", pointLight(0.3, 0.2, 3.0)},
            {"point below", pointLight(0.3, 0.2, -3.0)},
            {"directional above", towardLight(0.2, -0.3, 1.0)},
            {"directional below", towardLight(0.2, -0.3, -1.0)},
            {"point close below", pointLight(0.1, -0.2, -0.05)}};
}

TEST(ShadowVolumeMeshTest, OpenSheetShadowsFromEitherSide) {
    const Mesh sheet = quadSheet();
    for (const NamedLight& light : sheetLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkVolume(sheet, light.light, {.halfSize = 3.0});
        expectMeaningful(check);
        EXPECT_EQ(check.maxCount, 1);
    }
}

std::vector<NamedLight> openBoxLights() {
    std::vector<NamedLight> lights = standardLights();
    lights.push_back({"point inside", pointLight(0.2, -0.1, 0.3)});
    return lights;
}

TEST(ShadowVolumeMeshTest, OpenBoxShadowsAndLetsLightIn) {
    const Mesh box = openBox();
    for (const NamedLight& light : openBoxLights()) {
        SCOPED_TRACE(light.name);
        expectMeaningful(checkVolume(box, light.light, {.seed = 5}));
    }
    // Lit from above through the open top, the inside of the floor is lit, the space below
    // it in shadow.
    const Crossings floorInside = crossingsToLight(box, pointLight(0.15, -0.1, 4.0), glm::dvec3(0.1, 0.1, -0.9));
    EXPECT_EQ(floorInside.all, 0);
}

std::vector<NamedLight> finLights() {
    std::vector<NamedLight> lights = standardLights();
    lights.push_back({"point between fins", pointLight(0.3, 0.5, 0.1)});
    return lights;
}

TEST(ShadowVolumeMeshTest, NonManifoldFinsCountEveryFinCrossed) {
    const Mesh fins = threeFins();
    int maxCount = 0;
    for (const NamedLight& light : finLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkVolume(fins, light.light, {.halfSize = 3.0, .seed = 6});
        expectMeaningful(check);
        maxCount = std::max(maxCount, check.maxCount);
    }
    EXPECT_GE(maxCount, 2);  // behind two fins the summed volumes count 2
}

std::vector<NamedLight> roomLights() {
    return {{"point inside", pointLight(0.3, -0.4, 0.5)},
            {"point outside", pointLight(5.0, 4.0, 3.0)},
            {"directional", towardLight(0.3, 0.4, 1.0)}};
}

TEST(ShadowVolumeMeshTest, InwardRoomLitFromInsideIsLitInside) {
    // A single-shell room (closed, wound inward): lit from inside, nothing in it is shadowed
    // and everything outside is; lit from outside or by the sun, everything in it is shadowed.
    // The classic volume would get all three wrong (-1 all through the room and 0 outside it,
    // then 0 in the room).
    const Mesh room = inwardWound(splitCube(glm::vec3(0.0f), 2.0f));
    for (const NamedLight& light : roomLights()) {
        SCOPED_TRACE(light.name);
        expectMeaningful(checkVolume(room, light.light, {.seed = 7}));
    }
}

TEST(ShadowVolumeMeshTest, LightInsideClosedCasterShadowsEverythingOutside) {
    // A point light inside a closed outward sphere (a bulb): the far cap alone wraps all
    // directions once, so every point outside counts 1. (Inside the solid it counts 1 as well,
    // where no visible surface is.)
    const ShadowVolumeMesh bulb = build(uvSphere(16, 10, 1.0f));
    std::vector<glm::vec4> triangles;
    const ShadowVolumeCounts counts = bulb.appendVolume(pointLight(0.1, 0.2, -0.1), glm::dmat4(1.0), triangles);
    EXPECT_EQ(counts.silhouetteEdges, 0u);
    EXPECT_EQ(counts.capTriangles, bulb.triangleCount());
    for (const glm::dvec3& q : {glm::dvec3(3, 0, 0), glm::dvec3(-1, 2, 5), glm::dvec3(0.2, -0.1, -1.5)})
        EXPECT_NEAR(windingNumber(triangles, q), 1.0, kIntegerTolerance);
}

TEST(ShadowVolumeMeshTest, MirroredTargetTurnsVolumeInsideOut) {
    // toTarget with a negative determinant: the winding in target space is -1 in shadow, so the
    // caller flips the front face for mirrored instances as for their other draws.
    const glm::dmat4 mirror = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -2.0, 1.0)),
                                         glm::dvec3(-1.0, 1.0, 1.0));
    const Mesh cube = splitCube(glm::vec3(0.0f), 1.0f);
    for (const NamedLight& light : standardLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkVolume(cube, light.light, {.seed = 8}, mirror);
        expectMeaningful(check);
        EXPECT_EQ(check.maxCount, 1);
    }
    expectMeaningful(checkVolume(quadSheet(), pointLight(0.3, 0.2, -3.0), {.halfSize = 3.0}, mirror));
}

namespace {

// Both far-from-origin tests' scene: a cube and a sheet 1e7 from the origin (integer corners,
// exact in float), toTarget bringing them back near 0 and turning them, and three lights.
struct FarFromOrigin {
    glm::dvec3 far{1e7, -1e7, 1e7};
    glm::dmat4 toTarget{1.0};
    Mesh cube, sheet;
    std::vector<NamedLight> lights;
};

FarFromOrigin farFromOrigin() {
    FarFromOrigin scene;
    const glm::dvec3 far = scene.far;
    scene.toTarget = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 3.0))) *
                     glm::translate(glm::dmat4(1.0), -far);
    scene.cube = splitCube(glm::vec3(far), 2.0f);
    scene.sheet = quadSheet();
    for (glm::vec3& p : scene.sheet.positions) p = glm::vec3(glm::dvec3(p) * 2.0 + far + glm::dvec3(0, 0, -4));
    scene.lights = {{"point", pointLight(far.x + 3.3, far.y + 0.7, far.z + 5.1)},
                    {"point close", pointLight(far.x + 0.3, far.y - 0.2, far.z + 2.15)},
                    {"directional", towardLight(0.3, -0.5, 1.0)}};
    return scene;
}

} // namespace

TEST(ShadowVolumeMeshTest, FarFromOriginCameraRelativeTargetStaysExact) {
    // Mesh and light 1e7 from the origin (integer corners, exact in float), toTarget brings them
    // back near 0 and turns them. Rounded to float before that subtraction, the light would move
    // by up to half a unit and the vertices by a unit (float's step at 1e7): the shadow edges
    // would land wrong by far more than the boundary margin.
    const FarFromOrigin scene = farFromOrigin();
    const glm::dvec3& far = scene.far;
    const glm::dmat4& toTarget = scene.toTarget;
    const Mesh& cube = scene.cube;
    const Mesh& farSheet = scene.sheet;
    const std::vector<NamedLight>& lights = scene.lights;
    for (const NamedLight& light : lights) {
        SCOPED_TRACE(light.name);
        const Sampling sampling{.center = far, .halfSize = 6.0, .seed = 9};
        const VolumeCheck check = checkVolume(cube, light.light, sampling, toTarget);
        expectMeaningful(check, sampling);
        EXPECT_EQ(check.maxCount, 1);
        expectMeaningful(checkVolume(joined(cube, farSheet), light.light, sampling, toTarget), sampling);
    }
}

// ---- Posed (skinned or morphed) meshes: the adjacency built at rest, the positions posed ----

// The same floats, bit for bit, in the same order.
bool sameBits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    const auto same = [](const glm::vec4& x, const glm::vec4& y) { return keyOf(x) == keyOf(y); };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), same);
}

TEST(ShadowVolumeMeshTest, PosedAtRestIsTheRestVolumeBitForBit) {
    const glm::dmat4 toTarget = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 3.0))) *
                                glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -2.0, 1.0));
    const std::pair<std::string, Mesh> meshes[] = {{"cube", splitCube(glm::vec3(0.0f), 1.0f)},
                                                   {"sphere", uvSphere(16, 10, 1.0f)},
                                                   {"open box", openBox()},
                                                   {"fins", threeFins()},
                                                   {"room", inwardWound(splitCube(glm::vec3(0.0f), 2.0f))}};
    for (const auto& [name, mesh] : meshes) {
        const ShadowVolumeMesh volumeMesh = build(mesh);
        for (const NamedLight& light : standardLights()) {
            SCOPED_TRACE(name + ", " + light.name);
            // Without and with a bound (one the volume crosses).
            const ShadowVolumeBound crossed{glm::dvec3(toTarget * glm::dvec4(0.3, 0.0, -0.5, 1.0)), 2.5};
            for (const ShadowVolumeBound& bound : {ShadowVolumeBound{}, crossed}) {
                std::vector<glm::vec4> rest(1, glm::vec4(7.0f)), posed(1, glm::vec4(7.0f));  // appended after
                const ShadowVolumeCounts restCounts = volumeMesh.appendVolume(light.light, toTarget, rest, bound);
                const ShadowVolumeCounts posedCounts =
                    volumeMesh.appendVolume(light.light, toTarget, mesh.positions, posed, bound);
                EXPECT_GT(rest.size(), 1u);
                EXPECT_TRUE(sameBits(rest, posed));
                EXPECT_EQ(restCounts.silhouetteEdges, posedCounts.silhouetteEdges);
                EXPECT_EQ(restCounts.capTriangles, posedCounts.capTriangles);
            }
        }
    }
}

// The lights for the posed cubes below, which reach from z = -1 to 2: all outside them.
std::vector<NamedLight> posedCubeLights() {
    return {{"point outside", pointLight(3.0, 2.2, 3.6)},
            {"point above", pointLight(0.15, -0.1, 5.0)},
            {"point close to the raised top", pointLight(0.1, 0.2, 2.25)},
            {"directional diagonal", towardLight(1.0, 0.8, 1.2)},
            {"directional from below", towardLight(-0.2, 0.3, -1.0)}};
}

TEST(ShadowVolumeMeshTest, PosedCubeShadowsItsPosedShape) {
    // Each corner moved its own way (scaled and sheared by amounts that depend on where it is),
    // the top face (z = +1) raised by 1: no affine map, and the faces no longer planar. Every copy
    // of a corner goes to the same place, as a skin with equal weights on the seam would put it.
    const Mesh rest = splitCube(glm::vec3(0.0f), 1.0f);
    std::vector<glm::vec3> posed;
    for (const glm::vec3& p : rest.positions)
        posed.push_back({p.x * (1.0f + 0.2f * p.y) + 0.3f * p.z, p.y * (1.0f - 0.15f * p.x) + 0.1f * p.z,
                         p.z + (p.z > 0.0f ? 1.0f : 0.0f) + 0.1f * p.x * p.y});
    const Sampling sampling{.center = glm::dvec3(0.0, 0.0, 0.5), .seed = 10};
    for (const NamedLight& light : posedCubeLights()) {
        SCOPED_TRACE(light.name);
        expectMeaningful(checkPosedVolume(rest, posed, light.light, sampling), sampling);
    }
}

TEST(ShadowVolumeMeshTest, PosedIntoItselfStillShadowsExactly) {
    // Two cubes apart at rest (closed outward), posed to overlap, as an arm crossing the body:
    // the posed surface crosses itself but turns nothing inside out, so the count is the
    // entries, 2 behind both, and non-zero exactly in shadow.
    const Mesh rest =
        joined(splitCube(glm::vec3(-3.0f, 0.0f, 0.0f), 1.0f), splitCube(glm::vec3(3.0f, 0.0f, 0.0f), 1.0f));
    ASSERT_TRUE(build(rest).closedOutward());
    std::vector<glm::vec3> posed = rest.positions;
    for (std::size_t i = 0; i < posed.size(); ++i)
        posed[i] += i < 24 ? glm::vec3(3.0f, 0.0f, 0.0f) : glm::vec3(-2.0f + 0.1f * posed[i].z, 0.3f, 0.2f);
    const Sampling sampling{.seed = 11};
    for (const NamedLight& light : posedCubeLights()) {
        SCOPED_TRACE(light.name);
        expectMeaningful(checkPosedVolume(rest, posed, light.light, sampling), sampling);
    }
    const VolumeCheck alongX = checkPosedVolume(rest, posed, pointLight(5.0, 0.2, 0.1), {.seed = 12});
    expectMeaningful(alongX);
    EXPECT_EQ(alongX.maxCount, 2);
}

TEST(ShadowVolumeMeshTest, PosedInsideOutReadsLitInShadowOnlyWhereTurned) {
    // The top face (z = 1) pushed through the bottom one to z = -2: the posed cube is turned
    // inside out (its winding number is -1 between z = -2 and -1). What the header promises: the
    // count is still the facing triangles crossed, and reads lit in shadow only inside the
    // turned part. That it does read lit there is checked too, so that the header's warning
    // stays true.
    const Mesh rest = splitCube(glm::vec3(0.0f), 1.0f);
    std::vector<glm::vec3> posed = rest.positions;
    for (glm::vec3& p : posed)
        if (p.z > 0.0f) p.z = -2.0f;
    const Sampling sampling{.center = glm::dvec3(0.0, 0.0, -1.5), .halfSize = 3.0, .seed = 13};
    int litInShadow = 0;
    for (const NamedLight& light : posedCubeLights()) {
        SCOPED_TRACE(light.name);
        const VolumeCheck check = checkPosedVolume(rest, posed, light.light, sampling, InsideOut::Allowed);
        expectMeaningful(check, sampling);
        litInShadow += check.litInShadow;
    }
    EXPECT_GT(litInShadow, 0);
}

TEST(ShadowVolumeMeshTest, PosedSeamTakesTheFirstCopyOfEachCorner) {
    // The cube as exported (3 copies of each corner), its triangles in reverse order so that the
    // copy the indices refer to first is not the lowest index, every input vertex posed its own
    // way: the 3 copies of a corner land apart.
    Mesh rest = splitCube(glm::vec3(0.0f), 1.0f);
    std::vector<std::uint32_t> reversed;
    for (std::size_t t = rest.indices.size(); t >= 3; t -= 3)
        reversed.insert(reversed.end(), rest.indices.begin() + std::ptrdiff_t(t - 3),
                        rest.indices.begin() + std::ptrdiff_t(t));
    rest.indices = reversed;
    std::vector<glm::vec3> posed;
    for (std::size_t i = 0; i < rest.positions.size(); ++i)
        posed.push_back(1.1f * rest.positions[i] + 0.02f * float(i) * glm::vec3(1.0f, -0.6f, 0.3f));
    // The meshes made directly from the first and from the last copy of each corner.
    using Key = std::array<float, 3>;
    const auto keyOfCorner = [](const glm::vec3& p) { return Key{p.x, p.y, p.z}; };
    std::map<Key, std::uint32_t> first, last;
    for (std::uint32_t i : rest.indices) {
        first.try_emplace(keyOfCorner(rest.positions[i]), i);
        last[keyOfCorner(rest.positions[i])] = i;
    }
    ASSERT_EQ(first.size(), 8u);
    Mesh fromFirst = rest, fromLast = rest;
    for (std::size_t i = 0; i < rest.positions.size(); ++i) {
        fromFirst.positions[i] = posed[first.at(keyOfCorner(rest.positions[i]))];
        fromLast.positions[i] = posed[last.at(keyOfCorner(rest.positions[i]))];
    }
    ASSERT_NE(first, last);
    ASSERT_EQ(build(fromFirst).vertexCount(), 8u);
    ASSERT_EQ(build(fromLast).vertexCount(), 8u);

    const ShadowVolumeMesh volumeMesh = build(rest);
    const glm::dmat4 toTarget = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 1.0, -3.0));
    for (const NamedLight& light : {NamedLight{"point", pointLight(3.0, 2.2, 2.6)},
                                    NamedLight{"directional", towardLight(1.0, 0.8, 1.2)}}) {
        SCOPED_TRACE(light.name);
        std::vector<glm::vec4> posedOut, firstOut, lastOut;
        volumeMesh.appendVolume(light.light, toTarget, posed, posedOut);
        build(fromFirst).appendVolume(light.light, toTarget, firstOut);
        build(fromLast).appendVolume(light.light, toTarget, lastOut);
        EXPECT_TRUE(closedSurface(posedOut));  // no tear at the seams
        EXPECT_TRUE(sameBits(posedOut, firstOut));
        EXPECT_FALSE(sameBits(posedOut, lastOut));
    }
}

TEST(ShadowVolumeMeshTest, PosedRejectsWrongSize) {
    const Mesh rest = splitCube(glm::vec3(0.0f), 1.0f);
    const ShadowVolumeMesh cube = build(rest);
    const glm::dvec4 light = pointLight(3.0, 2.2, 2.6);
    std::vector<glm::vec4> out;
    std::vector<glm::vec3> fewer = rest.positions, more = rest.positions;
    fewer.pop_back();
    more.push_back(glm::vec3(0.0f));
    EXPECT_THROW(cube.appendVolume(light, glm::dmat4(1.0), fewer, out), std::invalid_argument);
    EXPECT_THROW(cube.appendVolume(light, glm::dmat4(1.0), more, out), std::invalid_argument);
    EXPECT_TRUE(out.empty());
    // The size is the constructor's positions.size(), unused positions included.
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    const std::vector<glm::vec3> usedOnly(positions.begin(), positions.begin() + 3);
    const ShadowVolumeMesh triangle(positions, {0, 1, 2});
    EXPECT_NO_THROW((void)triangle.appendVolume(light, glm::dmat4(1.0), positions, out));
    EXPECT_THROW(triangle.appendVolume(light, glm::dmat4(1.0), usedOnly, out), std::invalid_argument);
    const ShadowVolumeMesh empty;
    const std::vector<glm::vec3> none, one(1, glm::vec3(0.0f));
    EXPECT_NO_THROW((void)empty.appendVolume(light, glm::dmat4(1.0), none, out));
    EXPECT_THROW(empty.appendVolume(light, glm::dmat4(1.0), one, out), std::invalid_argument);
}

// ---- Bounded volumes: extruded to finite points just past a sphere in target space ----

// A target space for the bounded checks: translate * rotate * scale, so that the scale's
// components are toTarget's singular values and give the bound's radius in target space.
struct NamedTarget {
    std::string name;
    glm::dmat4 toTarget;
    double minScale = 1.0, maxScale = 1.0;
};

NamedTarget namedTarget(std::string name, const glm::dvec3& translation, double angle, const glm::dvec3& axis,
                        const glm::dvec3& scale) {
    const glm::dmat4 toTarget = glm::translate(glm::dmat4(1.0), translation) *
                                glm::rotate(glm::dmat4(1.0), angle, glm::normalize(axis)) *
                                glm::scale(glm::dmat4(1.0), scale);
    const glm::dvec3 size = glm::abs(scale);
    return {std::move(name), toTarget, std::min({size.x, size.y, size.z}), std::max({size.x, size.y, size.z})};
}

std::vector<NamedTarget> boundedTargets() {
    return {namedTarget("identity", glm::dvec3(0.0), 0.0, glm::dvec3(0, 0, 1), glm::dvec3(1.0)),
            namedTarget("turned, moved, scaled", glm::dvec3(0.5, -2.0, 1.0), 0.7, glm::dvec3(1, 2, 3),
                        glm::dvec3(1.7)),
            namedTarget("scaled unevenly", glm::dvec3(-3.0, 1.0, -6.0), -1.1, glm::dvec3(-2, 1, 0.5),
                        glm::dvec3(0.6, 1.9, 1.2)),
            namedTarget("mirrored", glm::dvec3(1.0, 0.0, -2.0), 0.4, glm::dvec3(0, 1, 1), glm::dvec3(1.3, -0.8, 1.0))};
}

struct NamedBound {
    std::string name;
    ShadowVolumeBound bound;
    bool holdsAll = false;
};

// Two bounds for a sampling, in target space: one that holds the whole sampled region (the cube,
// and the points past the mesh, all within sqrt(3) * halfSize + 1 of its center), so that every
// point is checked; and a smaller one off center that the volume crosses, so that it ends among
// the sampled points (those outside it are not checked).
std::vector<NamedBound> boundsFor(const Sampling& sampling, const NamedTarget& target) {
    const auto inTarget = [&](const glm::dvec3& p) { return glm::dvec3(target.toTarget * glm::dvec4(p, 1.0)); };
    const glm::dvec3 offCenter = sampling.center + sampling.halfSize * glm::dvec3(0.2, -0.3, -0.25);
    return {{"holding all", {inTarget(sampling.center), target.maxScale * (std::sqrt(3.0) * sampling.halfSize + 1.0)},
             true},
            {"crossed", {inTarget(offCenter), 0.3 * (target.minScale + target.maxScale) * sampling.halfSize}, false}};
}

// The mesh's volumes with bounds, in every target space of boundedTargets() and for both bounds
// of boundsFor(): inside the bound, the count is exactly the infinite volume's (checkTriangles,
// which also checks that the surface is closed and has no degenerate triangle). The crossed
// bound holds fewer points, so it is sampled 4 times as densely.
void checkBoundedVolumes(const Mesh& mesh, const std::vector<NamedLight>& lights, const Sampling& sampling) {
    for (const NamedTarget& target : boundedTargets())
        for (const NamedBound& bound : boundsFor(sampling, target)) {
            Sampling dense = sampling;
            if (!bound.holdsAll) dense.points *= 4;
            int inside = 0, kept = 0, shadowed = 0;
            for (const NamedLight& light : lights) {
                SCOPED_TRACE(target.name + ", " + bound.name + ", " + light.name);
                const VolumeCheck check = checkVolume(mesh, light.light, dense, target.toTarget, bound.bound);
                if (bound.holdsAll) {
                    EXPECT_EQ(check.outsideBound, 0);
                    expectMeaningful(check, dense);
                }
                EXPECT_GT(check.kept, (dense.points - check.outsideBound) * 9 / 10);
                inside += dense.points - check.outsideBound;
                kept += check.kept;
                shadowed += check.shadowed;
            }
            SCOPED_TRACE(target.name + ", " + bound.name);
            EXPECT_GT(inside, int(lights.size()) * dense.points / 20);
            EXPECT_GT(shadowed, kept / 20);
            EXPECT_LT(shadowed, kept - kept / 20);
        }
}

TEST(ShadowVolumeMeshTest, BoundedClosedVolumesCountExactlyInsideTheBound) {
    checkBoundedVolumes(splitCube(glm::vec3(0.0f), 1.0f), standardLights(), {});
    checkBoundedVolumes(uvSphere(16, 10, 1.0f), standardLights(), {.points = 400, .seed = 2});
    checkBoundedVolumes(joined(splitCube(glm::vec3(0.0f), 1.0f), splitCube(glm::vec3(1.0f, 0.0f, 0.0f), 1.0f)),
                        standardLights(), {.seed = 3});
}

TEST(ShadowVolumeMeshTest, BoundedSummedVolumesCountExactlyInsideTheBound) {
    checkBoundedVolumes(quadSheet(), sheetLights(), {.halfSize = 3.0});
    checkBoundedVolumes(openBox(), openBoxLights(), {.seed = 5});
    checkBoundedVolumes(threeFins(), finLights(), {.halfSize = 3.0, .seed = 6});
    checkBoundedVolumes(inwardWound(splitCube(glm::vec3(0.0f), 2.0f)), roomLights(), {.seed = 7});
}

TEST(ShadowVolumeMeshTest, BoundedVolumeAroundLightCloseToLargeTrianglesStaysExact) {
    // A light close to a large triangle sees its corners far apart: a far cap put just past the
    // sphere along each corner's ray would cut back through it between them (a chord of a wide
    // angle). Here the bound is small and right behind the caster, where that chord would pass.
    const Mesh sheet = quadSheet();
    const Mesh cube = splitCube(glm::vec3(0.0f), 1.0f);
    const glm::dvec4 closeBelow = pointLight(0.1, -0.2, -0.3), closeToFace = pointLight(0.1, 0.2, 1.3);
    for (const NamedTarget& target : boundedTargets()) {
        SCOPED_TRACE(target.name);
        const auto inTarget = [&](const glm::dvec3& p) { return glm::dvec3(target.toTarget * glm::dvec4(p, 1.0)); };
        const Sampling behindSheet{.center = glm::dvec3(0.0, 0.0, 1.2), .halfSize = 1.0, .points = 800, .seed = 14};
        const ShadowVolumeBound sheetBound{inTarget(behindSheet.center), target.maxScale * 1.0};
        const VolumeCheck sheetCheck = checkVolume(sheet, closeBelow, behindSheet, target.toTarget, sheetBound);
        EXPECT_GT(sheetCheck.kept, 200);
        EXPECT_GT(sheetCheck.shadowed, 50);
        const Sampling behindCube{.center = glm::dvec3(0.0, 0.0, -1.6), .halfSize = 1.0, .points = 800, .seed = 15};
        const ShadowVolumeBound cubeBound{inTarget(behindCube.center), target.maxScale * 1.0};
        const VolumeCheck cubeCheck = checkVolume(cube, closeToFace, behindCube, target.toTarget, cubeBound);
        EXPECT_GT(cubeCheck.kept, 200);
        EXPECT_GT(cubeCheck.shadowed, 50);
    }
}

// The emitted vertices that are not the mesh's own (toTarget * (p, 1), bit for bit): the
// extruded ones, or those of them not equal to their vertex.
std::vector<glm::vec4> extrudedVertices(const Mesh& mesh, const glm::dmat4& toTarget,
                                        const std::vector<glm::vec4>& triangles) {
    std::map<VertexKey, int> own;
    for (const glm::vec3& p : mesh.positions) own[keyOf(glm::vec4(toTarget * glm::dvec4(glm::dvec3(p), 1.0)))] = 1;
    std::vector<glm::vec4> extruded;
    for (const glm::vec4& v : triangles)
        if (!own.contains(keyOf(v))) extruded.push_back(v);
    return extruded;
}

TEST(ShadowVolumeMeshTest, BoundedExtrusionIsFiniteAndPastTheSphere) {
    // Every extruded vertex is a finite point (w = 1) outside the sphere, and not far past it:
    // for a point light within 16 times the distance from the light to the sphere's far side
    // (the farthest the cosine limit allows), for a directional one on the plane normal to the
    // light that touches the sphere's far side (within the margins). The surface stays closed
    // (checked with the counts too).
    const std::pair<std::string, Mesh> meshes[] = {{"cube", splitCube(glm::vec3(0.0f), 1.0f)},
                                                   {"sphere", uvSphere(16, 10, 1.0f)},
                                                   {"sheet", quadSheet()},
                                                   {"fins", threeFins()},
                                                   {"room", inwardWound(splitCube(glm::vec3(0.0f), 2.0f))}};
    const NamedLight lights[] = {{"point outside", pointLight(3.0, 2.2, 2.6)},
                                 {"point high above", pointLight(0.15, -0.1, 6.0)},
                                 {"point far", pointLight(-30.0, 12.0, 20.0)},
                                 {"directional diagonal", towardLight(1.0, 0.8, 1.2)},
                                 {"directional from below", towardLight(-0.2, 0.3, -1.0)}};
    for (const auto& [name, mesh] : meshes) {
        const ShadowVolumeMesh volumeMesh = build(mesh);
        for (const NamedTarget& target : boundedTargets())
            for (const NamedLight& light : lights) {
                SCOPED_TRACE(name + ", " + target.name + ", " + light.name);
                const glm::dvec3 center = glm::dvec3(target.toTarget * glm::dvec4(0.1, -0.2, 0.3, 1.0));
                const ShadowVolumeBound bound{center, 3.0 * target.maxScale};
                std::vector<glm::vec4> triangles;
                volumeMesh.appendVolume(light.light, target.toTarget, triangles, bound);
                EXPECT_TRUE(closedSurface(triangles));
                const std::vector<glm::vec4> extruded = extrudedVertices(mesh, target.toTarget, triangles);
                EXPECT_FALSE(extruded.empty());
                const bool directional = light.light.w == 0.0;
                const glm::dvec3 lightInTarget = glm::dvec3(target.toTarget * light.light);
                const glm::dvec3 away =
                    glm::normalize(glm::dvec3(target.toTarget * glm::dvec4(-glm::dvec3(light.light), 0.0)));
                for (const glm::vec4& v : extruded) {
                    ASSERT_EQ(v.w, 1.0f);
                    ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
                    const glm::dvec3 p(v);
                    EXPECT_GE(glm::distance(p, center), bound.radius);
                    if (directional)
                        EXPECT_LE(glm::dot(p - center, away), 1.01 * bound.radius);
                    else
                        EXPECT_LE(glm::distance(p, lightInTarget),
                                  16.01 * (glm::distance(lightInTarget, center) + bound.radius));
                }
            }
    }
}

TEST(ShadowVolumeMeshTest, BoundedExtrusionKeepsWideAnglesAtInfinity) {
    // A light close to the cube's top sees the corners of the top face more than 90 degrees
    // apart: no finite extrusion of those corners keeps the far cap between them past the
    // sphere, so they stay at infinity (w = 0) while the others are finite and outside it. The
    // counts are still exact inside (BoundedClosedVolumesCountExactlyInsideTheBound, with the
    // same light).
    const Mesh mesh = splitCube(glm::vec3(0.0f), 1.0f);
    std::vector<glm::vec4> triangles;
    const ShadowVolumeBound bound{glm::dvec3(0.0), 3.0};
    build(mesh).appendVolume(pointLight(0.1, 0.2, 1.08), glm::dmat4(1.0), triangles, bound);
    EXPECT_TRUE(closedSurface(triangles));
    int atInfinity = 0, finite = 0;
    for (const glm::vec4& v : extrudedVertices(mesh, glm::dmat4(1.0), triangles)) {
        if (v.w == 0.0f) {
            ++atInfinity;
            continue;
        }
        ++finite;
        EXPECT_EQ(v.w, 1.0f);
        EXPECT_GE(glm::length(glm::dvec3(v)), bound.radius);
    }
    EXPECT_GT(atInfinity, 0);
    EXPECT_GT(finite, 0);
}

TEST(ShadowVolumeMeshTest, BoundedLightInsideClosedCasterShadowsEverythingInTheBound) {
    // LightInsideClosedCasterShadowsEverythingOutside with a bound around the bulb: its far cap
    // now a closed finite shell past the bound, every point of the bound outside the bulb
    // still counts 1.
    const ShadowVolumeMesh bulb = build(uvSphere(16, 10, 1.0f));
    std::vector<glm::vec4> triangles;
    const ShadowVolumeBound bound{glm::dvec3(0.5, 0.0, -0.5), 4.0};
    bulb.appendVolume(pointLight(0.1, 0.2, -0.1), glm::dmat4(1.0), triangles, bound);
    EXPECT_TRUE(closedSurface(triangles));
    for (const glm::dvec3& q : {glm::dvec3(3, 0, 0), glm::dvec3(-1, 2, -2), glm::dvec3(0.2, -0.1, -1.5),
                                glm::dvec3(0.5, 0.0, 3.45)})
        EXPECT_NEAR(windingNumber(triangles, q), 1.0, kIntegerTolerance);
    for (const glm::vec4& v : extrudedVertices(uvSphere(16, 10, 1.0f), glm::dmat4(1.0), triangles)) {
        EXPECT_EQ(v.w, 1.0f);
        EXPECT_GE(glm::distance(glm::dvec3(v), bound.center), bound.radius);
    }
}

TEST(ShadowVolumeMeshTest, BoundedFarFromOriginCameraRelativeTargetStaysExact) {
    // FarFromOriginCameraRelativeTargetStaysExact with bounds: the bound is in target space,
    // near the origin, and its distances are measured after the subtraction.
    const FarFromOrigin scene = farFromOrigin();
    const glm::dvec3& far = scene.far;
    const glm::dmat4& toTarget = scene.toTarget;
    const Mesh& cube = scene.cube;
    const Mesh& farSheet = scene.sheet;
    const std::vector<NamedLight>& lights = scene.lights;
    const Sampling sampling{.center = far, .halfSize = 6.0, .seed = 9};
    const glm::dvec3 offCenter = glm::dvec3(toTarget * glm::dvec4(far + glm::dvec3(1.0, -1.5, -3.0), 1.0));
    const NamedBound bounds[] = {{"holding all", {glm::dvec3(0.0), std::sqrt(3.0) * 6.0 + 1.0}, true},
                                 {"crossed", {offCenter, 3.5}, false}};
    for (const NamedBound& bound : bounds)
        for (const NamedLight& light : lights) {
            SCOPED_TRACE(bound.name + ", " + light.name);
            for (const Mesh& mesh : {cube, joined(cube, farSheet)}) {
                const VolumeCheck check = checkVolume(mesh, light.light, sampling, toTarget, bound.bound);
                if (bound.holdsAll) {
                    EXPECT_EQ(check.outsideBound, 0);
                    expectMeaningful(check, sampling);
                } else {
                    EXPECT_GT(check.kept, 50);
                    EXPECT_GT(check.kept, (sampling.points - check.outsideBound) * 9 / 10);
                }
            }
        }
}

TEST(ShadowVolumeMeshTest, NoBoundIsTheInfiniteVolumeBitForBit) {
    // radius 0 (the default), a negative radius, or one that is not finite: extrusion to
    // infinity exactly as without the argument, for both overloads.
    const glm::dmat4 toTarget = glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 3.0))) *
                                glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -2.0, 1.0)),
                                           glm::dvec3(0.6, 1.9, 1.2));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const ShadowVolumeBound noBounds[] = {{},
                                          {glm::dvec3(1.0, 2.0, 3.0), 0.0},
                                          {glm::dvec3(1.0, 2.0, 3.0), -2.0},
                                          {glm::dvec3(0.0), nan},
                                          {glm::dvec3(0.0), inf},
                                          {glm::dvec3(nan, 0.0, 0.0), 3.0}};
    const std::pair<std::string, Mesh> meshes[] = {{"cube", splitCube(glm::vec3(0.0f), 1.0f)},
                                                   {"fins", threeFins()}};
    for (const auto& [name, mesh] : meshes) {
        const ShadowVolumeMesh volumeMesh = build(mesh);
        for (const NamedLight& light : standardLights()) {
            SCOPED_TRACE(name + ", " + light.name);
            std::vector<glm::vec4> infinite;
            volumeMesh.appendVolume(light.light, toTarget, infinite);
            for (const ShadowVolumeBound& bound : noBounds) {
                std::vector<glm::vec4> rest, posed;
                volumeMesh.appendVolume(light.light, toTarget, rest, bound);
                volumeMesh.appendVolume(light.light, toTarget, mesh.positions, posed, bound);
                EXPECT_TRUE(sameBits(infinite, rest));
                EXPECT_TRUE(sameBits(infinite, posed));
            }
        }
    }
}

// Not a test of correctness: prints what one frame's volume of a ~100k-triangle sphere costs
// on this machine (no assertion on time: it depends on the machine and its load).
TEST(ShadowVolumeMeshTest, PrintsTimeForLargeSphere) {
    const Mesh sphere = uvSphere(256, 200, 1.0f);
    const auto loadStart = std::chrono::steady_clock::now();
    const ShadowVolumeMesh mesh = build(sphere);
    const auto loadEnd = std::chrono::steady_clock::now();
    ASSERT_TRUE(mesh.closedOutward());
    // A skinned or morphed frame: every vertex moved its own way (bulged along z), the
    // adjacency kept from load. Rebuilding the mesh from the pose instead costs the load time.
    std::vector<glm::vec3> posed;
    for (const glm::vec3& p : sphere.positions) posed.push_back(p * (1.0f + 0.1f * p.z));
    std::vector<glm::vec4> out;
    const glm::dmat4 toTarget = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 1.0, -3.0));
    // The bounded variant: a sphere of radius 3 around the caster (in target space).
    const ShadowVolumeBound bound{glm::dvec3(0.5, 1.0, -3.0), 3.0};
    const NamedLight lights[] = {{"point", pointLight(3.0, 2.2, 2.6)}, {"directional", towardLight(1.0, 0.8, 1.2)}};
    const auto millisecondsSince = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    for (const NamedLight& light : lights) {
        constexpr int kFrames = 10;
        double best = std::numeric_limits<double>::infinity(), bestPosed = best, bestBounded = best,
               bestPosedBounded = best;
        ShadowVolumeCounts counts, boundedCounts;
        for (int frame = 0; frame < kFrames; ++frame) {
            out.clear();  // capacity kept, as a renderer reusing its buffer would
            auto start = std::chrono::steady_clock::now();
            counts = mesh.appendVolume(light.light, toTarget, out);
            best = std::min(best, millisecondsSince(start));
            out.clear();
            start = std::chrono::steady_clock::now();
            mesh.appendVolume(light.light, toTarget, posed, out);
            bestPosed = std::min(bestPosed, millisecondsSince(start));
            out.clear();
            start = std::chrono::steady_clock::now();
            boundedCounts = mesh.appendVolume(light.light, toTarget, out, bound);
            bestBounded = std::min(bestBounded, millisecondsSince(start));
            out.clear();
            start = std::chrono::steady_clock::now();
            mesh.appendVolume(light.light, toTarget, posed, out, bound);
            bestPosedBounded = std::min(bestPosedBounded, millisecondsSince(start));
        }
        std::printf("[ timing   ] %zu triangles, %s light: appendVolume %.2f ms, posed %.2f ms (best of %d), %llu "
                    "quads, %llu caps; load %.1f ms\n",
                    mesh.triangleCount(), light.name.c_str(), best, bestPosed, kFrames,
                    (unsigned long long)counts.silhouetteEdges, (unsigned long long)counts.capTriangles,
                    std::chrono::duration<double, std::milli>(loadEnd - loadStart).count());
        std::printf("[ timing   ] %zu triangles, %s light, bounded (radius %.0f): appendVolume %.2f ms, posed %.2f ms "
                    "(best of %d), %llu quads, %llu caps\n",
                    mesh.triangleCount(), light.name.c_str(), bound.radius, bestBounded, bestPosedBounded, kFrames,
                    (unsigned long long)boundedCounts.silhouetteEdges,
                    (unsigned long long)boundedCounts.capTriangles);
    }
}

} // namespace

// A point light resting on a surface (on the top face of a cube, on an open sheet) lies in the
// plane of that surface's triangles, up to rounding. Such a triangle casts nothing; classified
// by the sign of a rounding error, one triangle of a face could face the light and its
// neighbour not, and the quad on the edge between them would lie in the face and z-fight with
// it (the renderer shadowed the whole surface). Edge-on triangles are classified alike
// whichever side of the plane rounding puts the light: near caps in the classic volume, left
// out of the summed ones.
TEST(ShadowVolumeMeshTest, ALightInATrianglesPlaneGetsTheSameVolumeOnEitherSideOfIt) {
    const ShadowVolumeMesh cube = build(splitCube(glm::vec3(0.0f), 1.0f));
    const ShadowVolumeMesh sheet = build(quadSheet());
    for (const double off : {0.0, 1e-9, -1e-9}) {
        SCOPED_TRACE("light " + std::to_string(off) + " off the plane");
        // On the cube's top face (z = 1): the top is a near cap, every other triangle a far cap,
        // and the silhouette is the top's square.
        std::vector<glm::vec4> cubeVolume;
        const ShadowVolumeCounts onTop = cube.appendVolume(pointLight(0.2, -0.3, 1.0 + off), glm::dmat4(1.0), cubeVolume);
        EXPECT_EQ(onTop.silhouetteEdges, 4u);
        EXPECT_EQ(onTop.capTriangles, 12u);
        EXPECT_TRUE(closedSurface(cubeVolume));
        // In the sheet's plane (z = 0): nothing.
        std::vector<glm::vec4> sheetVolume;
        const ShadowVolumeCounts inSheet = sheet.appendVolume(pointLight(0.4, 0.1, off), glm::dmat4(1.0), sheetVolume);
        EXPECT_TRUE(sheetVolume.empty());
        EXPECT_EQ(inSheet.capTriangles + inSheet.silhouetteEdges, 0u);
    }
}

// The geometry shader's input: per triangle its corners, each followed by the far vertex of the
// triangle across the edge to the next corner. Every (next corner, corner, far vertex) must be
// a triangle of the mesh, wound as the mesh winds it (a closed mesh traverses a shared edge the
// other way); an open mesh has no such input.
TEST(ShadowVolumeMeshTest, AdjacencyIndicesNameTheTriangleAcrossEachEdge) {
    for (const Mesh& mesh : {splitCube(glm::vec3(0.0f), 1.0f), uvSphere(12, 8, 1.0f)}) {
        const ShadowVolumeMesh volume = build(mesh);
        const std::vector<std::uint32_t> adjacency = volume.adjacencyIndices();
        ASSERT_EQ(adjacency.size(), 6 * volume.triangleCount());
        const std::vector<glm::dvec3>& welded = volume.weldedPositions();
        // The mesh's triangles as positions, each in its three rotations.
        std::set<std::array<double, 9>> triangles;
        const auto key = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
            return std::array<double, 9>{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
        };
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::dvec3 a = corner(mesh, i), b = corner(mesh, i + 1), c = corner(mesh, i + 2);
            if (a == b || b == c || c == a) continue;  // dropped when welded
            triangles.insert(key(a, b, c));
            triangles.insert(key(b, c, a));
            triangles.insert(key(c, a, b));
        }
        for (std::size_t t = 0; t < volume.triangleCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3& from = welded[adjacency[6 * t + 2 * k]];
                const glm::dvec3& to = welded[adjacency[6 * t + (2 * k + 2) % 6]];
                const glm::dvec3& far = welded[adjacency[6 * t + 2 * k + 1]];
                EXPECT_TRUE(triangles.count(key(to, from, far))) << "triangle " << t << " edge " << k;
            }
    }
    EXPECT_TRUE(build(quadSheet()).adjacencyIndices().empty());
    EXPECT_TRUE(build(openBox()).adjacencyIndices().empty());
}
