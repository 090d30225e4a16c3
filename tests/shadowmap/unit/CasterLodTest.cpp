// caster_lod's levels (math/CasterLod.h): their recorded error bounds the distance between
// the level and the mesh as loaded, found here by brute force on random points of both
// surfaces; closed meshes stay closed at every level; levels shrink and index the same
// vertices.
#include "math/CasterLod.h"
#include "math/SurfaceDistance.h"

#include "engine/scene/Shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using shadowmap::SurfaceTriangle;

// One primitive as a mesh: normals up (the simplifier reads positions only), bounds, closedness.
engine::Mesh meshOf(engine::Primitive primitive) {
    primitive.normals.assign(primitive.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(glm::dvec3(p));
    engine::Mesh mesh;
    mesh.bounds = primitive.bounds;
    mesh.primitives.push_back(std::move(primitive));
    mesh.closed = engine::isClosedSurface(mesh);
    return mesh;
}

// A torus (ring radius R, tube radius r) of segments x sides quads, split as glTF exporters
// split it: the last ring of vertices repeats the first (a UV seam) with its own UVs, so it
// is closed only once welded by position. Bumps make the simplifier's error vary.
engine::Mesh torusMesh(int segments, int sides, double bumps) {
    engine::Primitive primitive;
    const double R = 2.0, r = 0.6;
    for (int i = 0; i <= segments; ++i)
        for (int j = 0; j <= sides; ++j) {
            const double u = 2.0 * M_PI * (i % segments) / segments, v = 2.0 * M_PI * (j % sides) / sides;
            const double tube = r * (1.0 + bumps * std::sin(5.0 * u) * std::cos(3.0 * v));
            primitive.positions.emplace_back((R + tube * std::cos(v)) * std::cos(u), tube * std::sin(v),
                                             (R + tube * std::cos(v)) * std::sin(u));
            primitive.texcoords.emplace_back(float(i) / segments, float(j) / sides);
        }
    const auto at = [sides](int i, int j) { return static_cast<std::uint32_t>(i * (sides + 1) + j); };
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < sides; ++j)
            for (const std::uint32_t index : {at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)})
                primitive.indices.push_back(index);
    return meshOf(std::move(primitive));
}

// A wavy open sheet: its border must survive (locked).
engine::Mesh sheetMesh(int n) {
    engine::Primitive primitive;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double x = double(i) / n * 4.0 - 2.0, z = double(j) / n * 4.0 - 2.0;
            primitive.positions.emplace_back(x, 0.2 * std::sin(1.5 * x) * std::cos(z), z);
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const std::uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            for (const std::uint32_t index : {a, b, c, c, b, d}) primitive.indices.push_back(index);
        }
    return meshOf(std::move(primitive));
}

// `count` points uniform by area on the surface.
std::vector<glm::dvec3> randomPoints(const std::vector<SurfaceTriangle>& surface, int count, std::mt19937& random) {
    std::vector<double> areas;
    for (const SurfaceTriangle& t : surface) areas.push_back(glm::length(glm::cross(t[1] - t[0], t[2] - t[0])));
    std::discrete_distribution<std::size_t> pick(areas.begin(), areas.end());
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> points;
    for (int k = 0; k < count; ++k) {
        const SurfaceTriangle& t = surface[pick(random)];
        double u = unit(random), v = unit(random);
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        points.push_back(t[0] + (t[1] - t[0]) * u + (t[2] - t[0]) * v);
    }
    return points;
}

// The largest distance from the points to the surface, over every triangle (brute force).
double largestDistance(const std::vector<glm::dvec3>& points, const std::vector<SurfaceTriangle>& surface) {
    double largest = 0.0;
    for (const glm::dvec3& p : points) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const SurfaceTriangle& t : surface) nearest = std::min(nearest, shadowmap::pointTriangleDistance(p, t));
        largest = std::max(largest, nearest);
    }
    return largest;
}

// The two-sided distance on random points of both surfaces, and the corners of both.
double sampledHausdorff(const std::vector<SurfaceTriangle>& a, const std::vector<SurfaceTriangle>& b,
                        std::mt19937& random) {
    std::vector<glm::dvec3> onA = randomPoints(a, 1500, random), onB = randomPoints(b, 1500, random);
    for (const SurfaceTriangle& t : a) onA.insert(onA.end(), t.begin(), t.end());
    for (const SurfaceTriangle& t : b) onB.insert(onB.end(), t.begin(), t.end());
    return std::max(largestDistance(onA, b), largestDistance(onB, a));
}

void expectValidLevels(const engine::Mesh& mesh, const std::vector<shadowmap::CasterLevel>& levels) {
    std::size_t last = mesh.triangleCount();
    double lastError = 0.0;
    for (const shadowmap::CasterLevel& level : levels) {
        ASSERT_EQ(level.indices.size(), mesh.primitives.size());
        EXPECT_LE(static_cast<double>(level.triangles), 0.75 * static_cast<double>(last)) << "at least a quarter smaller";
        EXPECT_GE(level.error, lastError) << "errors grow along the list";
        std::size_t triangles = 0;
        for (std::size_t p = 0; p < level.indices.size(); ++p) {
            triangles += level.indices[p].size() / 3;
            for (const std::uint32_t index : level.indices[p]) ASSERT_LT(index, mesh.primitives[p].positions.size());
        }
        EXPECT_EQ(triangles, level.triangles);
        last = level.triangles;
        lastError = level.error;
    }
}

} // namespace

TEST(SurfaceDistance, PointTriangleDistanceInEachRegion) {
    const SurfaceTriangle t{glm::dvec3(0, 0, 0), glm::dvec3(2, 0, 0), glm::dvec3(0, 2, 0)};
    EXPECT_DOUBLE_EQ(shadowmap::pointTriangleDistance({0.5, 0.5, 3.0}, t), 3.0);            // face
    EXPECT_DOUBLE_EQ(shadowmap::pointTriangleDistance({-3.0, -4.0, 0.0}, t), 5.0);          // corner
    EXPECT_DOUBLE_EQ(shadowmap::pointTriangleDistance({1.0, -2.0, 0.0}, t), 2.0);           // edge
    EXPECT_NEAR(shadowmap::pointTriangleDistance({2.0, 2.0, 0.0}, t), std::sqrt(2.0), 1e-12);  // hypotenuse
}

TEST(SurfaceDistance, BoundIsAtLeastTheBruteForceDistanceAndNotFarAbove) {
    // A square and the same square lifted and tilted: every distance is known by brute force.
    const std::vector<SurfaceTriangle> flat{{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)},
                                            {glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0)}};
    const std::vector<SurfaceTriangle> tilted{{glm::dvec3(0, 0, 0.1), glm::dvec3(1, 0, 0.3), glm::dvec3(0, 1, 0.1)},
                                              {glm::dvec3(1, 0, 0.3), glm::dvec3(1, 1, 0.3), glm::dvec3(0, 1, 0.1)}};
    shadowmap::SurfaceDistanceOptions options;
    options.absoluteTolerance = 0.01;
    options.relativeTolerance = 0.0;
    options.maxDepth = 10;
    const double bound = shadowmap::distanceBound(tilted, flat, options);
    const double truth = 0.3;  // the lifted edge's height
    EXPECT_GE(bound, truth);
    // Pieces are refined until their cover radius is at most the tolerance, 0.01.
    EXPECT_LE(bound, truth + 0.01 + 1e-12);
    // Nearer than the floor: the floor.
    options.atLeast = 0.5;
    EXPECT_EQ(shadowmap::distanceBound(tilted, flat, options), 0.5);
}

TEST(CasterLod, RecordedErrorBoundsTheDistanceOnSampledPoints) {
    std::mt19937 random(11);
    for (const engine::Mesh& mesh : {torusMesh(48, 24, 0.15), sheetMesh(40)}) {
        const std::vector<shadowmap::CasterLevel> levels = shadowmap::simplifiedLevels(mesh);
        // What the simplifier saw of the torus without its seams: no level may be open.
        if (mesh.closed)
            for (const shadowmap::CasterLevel& level : levels) EXPECT_TRUE(shadowmap::levelIsClosed(mesh, level));
        ASSERT_GE(levels.size(), 2u) << "halving a 2304/3200-triangle mesh gives levels";
        expectValidLevels(mesh, levels);
        const std::vector<SurfaceTriangle> original = shadowmap::meshTriangles(mesh);
        for (std::size_t l = 0; l < levels.size(); ++l) {
            const double sampled = sampledHausdorff(original, shadowmap::levelTriangles(mesh, levels[l]), random);
            EXPECT_GT(sampled, 0.0) << "level " << l << " changed the surface";
            // The recorded error is an upper bound (no tolerance) ...
            EXPECT_LE(sampled, levels[l].error) << "level " << l << " of " << mesh.triangleCount();
            // ... and a useful one: measured at most 1.6x the sampled maximum on these meshes
            // (its cover radius and the previous level's error as a floor); 3x fails a bound
            // that stopped measuring.
            EXPECT_LE(levels[l].error, 3.0 * sampled + 1e-6) << "level " << l;
        }
    }
}

TEST(CasterLod, AClosedMeshStaysClosedAtEveryLevel) {
    // Tori split at their UV seams (closed once welded), simplified as opaque casters are
    // (seams welded) and as alpha-masked ones are (seams kept: their UVs are read).
    for (const bool readsTexcoords : {false, true})
        for (const engine::Mesh& mesh : {torusMesh(64, 32, 0.1), torusMesh(40, 20, 0.0)}) {
            ASSERT_TRUE(mesh.closed);
            const std::vector<shadowmap::CasterLevel> levels = shadowmap::simplifiedLevels(mesh, {readsTexcoords});
            ASSERT_FALSE(levels.empty()) << readsTexcoords;
            for (std::size_t l = 0; l < levels.size(); ++l)
                EXPECT_TRUE(shadowmap::levelIsClosed(mesh, levels[l])) << l << " " << readsTexcoords;
        }
    // The check itself: dropping one triangle of a level opens it.
    const engine::Mesh mesh = torusMesh(40, 20, 0.0);
    std::vector<shadowmap::CasterLevel> levels = shadowmap::simplifiedLevels(mesh);
    ASSERT_FALSE(levels.empty());
    levels[0].indices[0].resize(levels[0].indices[0].size() - 3);
    EXPECT_FALSE(shadowmap::levelIsClosed(mesh, levels[0]));
}

TEST(CasterLod, AnOpenSheetKeepsItsBorder) {
    const engine::Mesh mesh = sheetMesh(40);
    ASSERT_FALSE(mesh.closed);
    const std::vector<shadowmap::CasterLevel> levels = shadowmap::simplifiedLevels(mesh);
    ASSERT_FALSE(levels.empty());
    // Locked borders: the sheet's square outline is there at every level, so the shadow's
    // outer edge stays where it was. Every border vertex is still used.
    const engine::Primitive& primitive = mesh.primitives[0];
    for (const shadowmap::CasterLevel& level : levels) {
        std::vector<bool> used(primitive.positions.size(), false);
        for (const std::uint32_t index : level.indices[0]) used[index] = true;
        for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
            const glm::vec3& p = primitive.positions[v];
            const bool border = std::abs(std::abs(p.x) - 2.0f) < 1e-6f || std::abs(std::abs(p.z) - 2.0f) < 1e-6f;
            if (border) {
                EXPECT_TRUE(used[v]) << "border vertex " << v;
            }
        }
    }
}

TEST(CasterLod, ABoxHasNoCoarserLevel) {
    // 12 triangles with every corner on the border of its face's split vertices: nothing to
    // remove that keeps the shape (and closedness); no level rather than a useless one.
    const engine::Mesh box = engine::boxMesh("box", glm::dvec3(1.0));
    EXPECT_TRUE(shadowmap::simplifiedLevels(box).empty());
}
