// Compressed glTF (KHR_draco_mesh_compression, EXT_meshopt_compression with
// KHR_mesh_quantization) decodes to the same world-space triangles as the uncompressed
// file, within the error the compression's quantization allows; and corrupt compressed data
// is one clear InputError. The plain and the Draco 2CylinderEngine come from Debian's
// assimp-testmodels; the meshopt copies are made here with Debian's gltfpack.
#include "gltf_test_support.h"
#include "compressed_seeds.h"  // tools/fuzz/: small Draco and meshopt files
#include "../support/AssimpTestModels.h"

#include "engine/gltf/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <unordered_map>

namespace {

namespace fs = std::filesystem;
using gltf_test::TempDir;
using gltf_test::expectLoadError;
using Triangle = std::array<glm::dvec3, 3>;

fs::path plainEngine() { return engine::test::kAssimpGltf2Models / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb"; }
fs::path dracoEngine() { return engine::test::kAssimpGltf2Models / "draco/2CylinderEngine.gltf"; }

// A triangle with two corners at the same position covers nothing: both encoders drop
// them (Draco when it deduplicates points, gltfpack when it filters triangles), and with
// them the vertices only they used.
bool isDegenerate(const engine::Primitive& primitive, std::size_t first) {
    const glm::vec3& a = primitive.positions[primitive.indices[first]];
    const glm::vec3& b = primitive.positions[primitive.indices[first + 1]];
    const glm::vec3& c = primitive.positions[primitive.indices[first + 2]];
    return a == b || b == c || a == c;
}

std::size_t coveringTriangles(const engine::Primitive& primitive) {
    std::size_t count = 0;
    for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) count += !isDegenerate(primitive, i);
    return count;
}

// Every triangle that covers something, of every mesh instance, in world space (double, as
// the renderer composes).
std::vector<Triangle> worldTriangles(const engine::Scene& scene, bool keepDegenerate = false) {
    std::vector<Triangle> triangles;
    for (const engine::MeshInstance& instance : scene.meshInstances)
        for (const engine::Primitive& primitive : scene.meshes[instance.mesh].primitives)
            for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
                if (!keepDegenerate && isDegenerate(primitive, i)) continue;
                Triangle triangle;
                for (int k = 0; k < 3; ++k)
                    triangle[k] = glm::dvec3(instance.world * glm::dvec4(glm::dvec3(primitive.positions[primitive.indices[i + k]]), 1.0));
                triangles.push_back(triangle);
            }
    return triangles;
}

// Largest vertex distance between two triangles, over the three rotations that keep the
// winding (a decoder may start a triangle at another corner, never flip it).
double triangleDistance(const Triangle& a, const Triangle& b) {
    double best = INFINITY;
    for (int r = 0; r < 3; ++r) {
        double worst = 0;
        for (int k = 0; k < 3; ++k) worst = std::max(worst, glm::length(a[k] - b[(k + r) % 3]));
        best = std::min(best, worst);
    }
    return best;
}

// For each triangle of `from`, the distance to the nearest triangle of `to`. Triangles are
// bucketed by centroid in cells of `cell` (> twice the expected error), so only the 27
// cells around a centroid are searched; a triangle with no match there is infinitely far.
std::vector<double> nearestTriangleDistances(const std::vector<Triangle>& from, const std::vector<Triangle>& to,
                                             double cell) {
    const auto key = [cell](const glm::dvec3& p) {
        const glm::i64vec3 c(glm::floor(p / cell));
        return (c.x * 73856093) ^ (c.y * 19349663) ^ (c.z * 83492791);
    };
    const auto centroid = [](const Triangle& t) { return (t[0] + t[1] + t[2]) / 3.0; };
    std::unordered_multimap<std::int64_t, std::size_t> buckets;
    for (std::size_t i = 0; i < to.size(); ++i) buckets.emplace(key(centroid(to[i])), i);
    std::vector<double> distances;
    for (const Triangle& triangle : from) {
        const glm::dvec3 c = centroid(triangle);
        double nearest = INFINITY;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto range = buckets.equal_range(key(c + glm::dvec3(dx, dy, dz) * cell));
                    for (auto it = range.first; it != range.second; ++it)
                        nearest = std::min(nearest, triangleDistance(triangle, to[it->second]));
                }
        distances.push_back(nearest);
    }
    return distances;
}

double shortestEdge(const Triangle& t) {
    return std::min({glm::length(t[0] - t[1]), glm::length(t[1] - t[2]), glm::length(t[2] - t[0])});
}

// The bounds of `triangles`' corners.
engine::Aabb boundsOf(const std::vector<Triangle>& triangles) {
    engine::Aabb bounds;
    for (const Triangle& triangle : triangles)
        for (const glm::dvec3& corner : triangle) bounds.extend(corner);
    return bounds;
}

double largestExtent(const engine::Aabb& bounds) {
    const glm::dvec3 size = bounds.max - bounds.min;
    return std::max({size.x, size.y, size.z});
}

// Runs Debian's gltfpack (tools/install-deps.sh installs it) on the plain engine.
fs::path gltfpack(const TempDir& dir, const std::string& output, const std::string& flags) {
    const fs::path out = dir / output;
    const std::string command = "gltfpack -i '" + plainEngine().string() + "' -o '" + out.string() + "' " + flags + " > '" +
                                (dir / "gltfpack.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
}

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
}
void writeJson(const fs::path& file, const nlohmann::json& json) { std::ofstream(file) << json.dump(); }

struct Comparison {
    std::size_t plainTriangles = 0, otherTriangles = 0;
    std::size_t collapsible = 0;  // plain triangles with an edge <= 2 * bound
    double worstPlainToOther = 0, worstOtherToPlain = 0;
    double extent = 0;
};

void expectBoundsNear(const engine::Aabb& actual, const engine::Aabb& expected, double bound) {
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(actual.min[axis], expected.min[axis], bound) << "axis " << axis;
        EXPECT_NEAR(actual.max[axis], expected.max[axis], bound) << "axis " << axis;
    }
}

// `bound`: the largest distance a vertex may move. Two corners closer than 2 * bound may be
// welded, so plain triangles with such an edge may be missing from `other`.
Comparison compareWithPlain(const engine::Scene& other, double bound) {
    const engine::Scene plain = engine::loadGltf(plainEngine());
    const std::vector<Triangle> a = worldTriangles(plain), b = worldTriangles(other);
    Comparison result;
    result.plainTriangles = a.size();
    result.otherTriangles = b.size();
    const double cell = std::max(8 * bound, 1e-3 * largestExtent(plain.worldBounds));
    // A plain triangle with two corners closer than 2 * bound may have been welded to a
    // line and dropped by the encoder: such triangles may lack a match (counted apart).
    const std::vector<double> plainToOther = nearestTriangleDistances(a, b, cell);
    std::size_t unmatchedCollapsible = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool collapsible = shortestEdge(a[i]) <= 2 * bound;
        result.collapsible += collapsible;
        if (collapsible && plainToOther[i] > bound) ++unmatchedCollapsible;
        else result.worstPlainToOther = std::max(result.worstPlainToOther, plainToOther[i]);
    }
    for (double distance : nearestTriangleDistances(b, a, cell))
        result.worstOtherToPlain = std::max(result.worstOtherToPlain, distance);
    result.extent = largestExtent(plain.worldBounds);
    std::printf("covering triangles plain %zu, other %zu; plain ones with an edge <= 2 x bound %zu, of which without "
                "a match %zu; worst distance plain->other %.6g, other->plain %.6g (bound %.6g); scene extent %.6g\n",
                result.plainTriangles, result.otherTriangles, result.collapsible, unmatchedCollapsible,
                result.worstPlainToOther, result.worstOtherToPlain, bound, result.extent);
    // Every triangle of `other` matches one of plain, every plain one does too unless it
    // could have collapsed, and the counts differ by no more than the collapsed ones.
    EXPECT_LE(result.otherTriangles, result.plainTriangles);
    EXPECT_LE(result.plainTriangles - std::min(result.plainTriangles, result.otherTriangles), unmatchedCollapsible);
    EXPECT_LE(result.worstPlainToOther, bound);
    EXPECT_LE(result.worstOtherToPlain, bound);
    return result;
}

TEST(GltfCompressed, DracoEngineDecodesToThePlainTriangles) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    const engine::Scene plain = engine::loadGltf(plainEngine());
    const engine::Scene draco = engine::loadGltf(dracoEngine());
    ASSERT_EQ(draco.meshes.size(), plain.meshes.size());
    ASSERT_EQ(draco.meshInstances.size(), plain.meshInstances.size());
    std::size_t sameOrder = 0, closedPlain = 0, closedDraco = 0;
    for (std::size_t m = 0; m < plain.meshes.size(); ++m) {
        ASSERT_EQ(draco.meshes[m].primitives.size(), plain.meshes[m].primitives.size());
        for (std::size_t p = 0; p < plain.meshes[m].primitives.size(); ++p) {
            const engine::Primitive& a = plain.meshes[m].primitives[p];
            const engine::Primitive& b = draco.meshes[m].primitives[p];
            // Never more triangles; fewer only where quantization collapsed some (checked
            // scene-wide below).
            EXPECT_LE(coveringTriangles(b), coveringTriangles(a)) << "meshes[" << m << "].primitives[" << p << "]";
            sameOrder += a.indices == b.indices;
        }
        closedPlain += plain.meshes[m].closed;
        closedDraco += draco.meshes[m].closed;
        // Quantization welds corners that were apart, which can close a mesh's last gaps,
        // never open one: the closed meshes stay closed (the backface variant relies on it).
        if (plain.meshes[m].closed) EXPECT_TRUE(draco.meshes[m].closed) << "meshes[" << m << "]";
        if (plain.meshes[m].closed != draco.meshes[m].closed)
            std::printf("meshes[%zu] '%s': closed after Draco's welding only\n", m, plain.meshes[m].name.c_str());
    }
    // Draco's edgebreaker reorders points and faces: index lists compare only as sets.
    std::printf("primitives whose index list Draco kept as it was: %zu; closed meshes plain %zu, Draco %zu\n",
                sameOrder, closedPlain, closedDraco);

    // Every Draco stream in the file quantizes POSITION to 11 bits over a cube the size of
    // its mesh's largest extent (read with libdraco's AttributeQuantizationTransform: 34
    // primitives, all 11 bits). A vertex moves by at most half a step per axis, so by
    // sqrt(3)/2 * extent / (2^11 - 1) in object space, times the largest scale of the
    // instance's M in world space.
    double bound = 0;
    for (const engine::MeshInstance& instance : plain.meshInstances) {
        double scale = 0;
        for (int column = 0; column < 3; ++column) scale = std::max(scale, glm::length(glm::dvec3(instance.world[column])));
        bound = std::max(bound, std::sqrt(3.0) / 2.0 * largestExtent(plain.meshes[instance.mesh].bounds) / 2047.0 * scale);
    }
    compareWithPlain(draco, bound);
    // Draco keeps the points no triangle uses, as the plain file has them: the bounds the
    // renderer culls with and the shadow plugin fits its frusta to are the plain file's.
    expectBoundsNear(draco.worldBounds, plain.worldBounds, bound);
    std::printf("Draco position bound %.6g\n", bound);
}

// gltfpack -cc: EXT_meshopt_compression (OCTAHEDRAL normals, index and vertex codecs) over
// KHR_mesh_quantization (14-bit positions dequantized by the node transform), with a
// fallback buffer without data. gltfpack also merges meshes and reorders vertices and
// triangles for the vertex cache, so only the world-space triangle sets are compared.
TEST(GltfCompressed, MeshoptQuantizedEngineDecodesToThePlainTriangles) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const engine::Scene packed = engine::loadGltf(gltfpack(dir, "engine.glb", "-cc"));
    const engine::Scene plain = engine::loadGltf(plainEngine());
    // gltfpack quantizes positions to 14 bits over one box around all meshes (its default
    // -vp 14): half a step per axis, sqrt(3)/2 steps in space, of step extent / (2^14 - 1).
    // The float32 dequantization transform adds rounding of ~1e-7 of the coordinates,
    // a thousandth of a step: 1 % covers it.
    const double bound = 1.01 * std::sqrt(3.0) / 2.0 * largestExtent(plain.worldBounds) / 16383.0;
    compareWithPlain(packed, bound);
    // gltfpack drops the vertices no triangle uses, so the bounds the renderer culls with and
    // the shadow plugin fits its frusta to must be those of the decoded triangles, in world
    // space: read without the dequantizing node transform they would span 0..16383.
    expectBoundsNear(packed.worldBounds, boundsOf(worldTriangles(packed, /*keepDegenerate=*/true)), bound);
}

// gltfpack -cc -noq: meshopt without quantization, as a .gltf with a separate .bin. The
// positions are the file's floats; only gltfpack's baking of node transforms into merged
// meshes rounds them (float32: ~1e-7 of the coordinates; bound 1e-5 of the scene extent).
TEST(GltfCompressed, MeshoptFloatEngineDecodesToThePlainTriangles) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const engine::Scene packed = engine::loadGltf(gltfpack(dir, "engine.gltf", "-cc -noq"));
    const engine::Scene plain = engine::loadGltf(plainEngine());
    const double bound = 1e-5 * largestExtent(plain.worldBounds);
    compareWithPlain(packed, bound);
}

// --- bad compressed data: one InputError naming file, object and reason -----------------

// The Draco engine copied into `dir` with its JSON changed by `edit` and its .bin by
// `editBin`.
template <typename EditJson, typename EditBin>
fs::path brokenDracoEngine(const TempDir& dir, EditJson edit, EditBin editBin) {
    nlohmann::json document = readJson(dracoEngine());
    edit(document);
    std::ifstream in(dracoEngine().parent_path() / "2CylinderEngine.bin", std::ios::binary);
    std::vector<char> bin((std::istreambuf_iterator<char>(in)), {});
    editBin(document, bin);
    std::ofstream(dir / "2CylinderEngine.bin", std::ios::binary).write(bin.data(), static_cast<std::streamsize>(bin.size()));
    writeJson(dir / "engine.gltf", document);
    return dir / "engine.gltf";
}
nlohmann::json& firstDracoExtension(nlohmann::json& document) {
    return document["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
}
const auto kNoBinEdit = [](const nlohmann::json&, std::vector<char>&) {};

TEST(GltfCompressedBadInput, CorruptDracoStream) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenDracoEngine(dir, [](nlohmann::json&) {}, [](nlohmann::json& document, std::vector<char>& bin) {
        const nlohmann::json& view = document["bufferViews"][firstDracoExtension(document)["bufferView"].get<int>()];
        const std::size_t offset = view.value("byteOffset", std::size_t{0});
        std::fill_n(bin.begin() + static_cast<std::ptrdiff_t>(offset), 16, '\xff');  // the "DRACO" magic and header
    });
    expectLoadError(file, {"engine.gltf", "meshes[0]", "primitives[0]", "KHR_draco_mesh_compression",
                           "does not decode"});
}

TEST(GltfCompressedBadInput, TruncatedDracoStream) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenDracoEngine(dir, [](nlohmann::json& document) {
        nlohmann::json& view = document["bufferViews"][firstDracoExtension(document)["bufferView"].get<int>()];
        view["byteLength"] = view["byteLength"].get<int>() / 2;
    }, kNoBinEdit);
    expectLoadError(file, {"engine.gltf", "meshes[0]", "primitives[0]", "does not decode"});
}

TEST(GltfCompressedBadInput, DracoAttributeIdThatDoesNotExist) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenDracoEngine(dir, [](nlohmann::json& document) {
        firstDracoExtension(document)["attributes"]["POSITION"] = 99;
    }, kNoBinEdit);
    expectLoadError(file, {"meshes[0]", "primitives[0]", "POSITION", "no attribute with id 99"});
}

TEST(GltfCompressedBadInput, DracoAccessorCountThatLies) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenDracoEngine(dir, [](nlohmann::json& document) {
        const int accessor = document["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
        document["accessors"][accessor]["count"] = document["accessors"][accessor]["count"].get<int>() + 1;
    }, kNoBinEdit);
    expectLoadError(file, {"meshes[0]", "primitives[0]", "POSITION", "is not the Draco mesh's point count"});
}

// The gltfpack -cc -noq engine (.gltf + .bin) with its JSON changed by `edit`.
template <typename Edit>
fs::path brokenMeshoptEngine(const TempDir& dir, Edit edit) {
    const fs::path file = gltfpack(dir, "engine.gltf", "-cc -noq");
    nlohmann::json document = readJson(file);
    edit(document);
    writeJson(file, document);
    return file;
}
nlohmann::json& meshoptOf(nlohmann::json& view) { return view["extensions"]["EXT_meshopt_compression"]; }

TEST(GltfCompressedBadInput, TruncatedMeshoptStream) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        nlohmann::json& extension = meshoptOf(document["bufferViews"][0]);
        extension["byteLength"] = extension["byteLength"].get<int>() / 2;
    });
    expectLoadError(file, {"engine.gltf", "bufferViews[0]", "does not decode", "corrupt or truncated"});
}

TEST(GltfCompressedBadInput, MeshoptByteLengthThatLies) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        document["bufferViews"][0]["byteLength"] = document["bufferViews"][0]["byteLength"].get<int>() + 4;
    });
    expectLoadError(file, {"bufferViews[0]", "is not the decoded size"});
}

TEST(GltfCompressedBadInput, MeshoptStreamPastItsBuffer) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        meshoptOf(document["bufferViews"][0])["byteOffset"] = 1u << 30;
    });
    expectLoadError(file, {"bufferViews[0]", "extensions.EXT_meshopt_compression.byteLength", "runs past the end of buffers[0]"});
}

TEST(GltfCompressedBadInput, UnknownMeshoptFilter) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        meshoptOf(document["bufferViews"][0])["filter"] = "WAVELET";
    });
    expectLoadError(file, {"bufferViews[0]", "filter 'WAVELET' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL"});
}

// An index stream decodes fine but names vertices the (shortened) POSITION accessor lacks:
// the decoded indices are checked like any file's.
TEST(GltfCompressedBadInput, MeshoptIndexPastTheVertexCount) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        for (const char* semantic : {"POSITION", "NORMAL"}) {
            const int accessor = document["meshes"][0]["primitives"][0]["attributes"][semantic];
            document["accessors"][accessor]["count"] = 3;
        }
    });
    expectLoadError(file, {"used as indices of meshes[0]", "is past the vertex count 3"});
}

TEST(GltfCompressedBadInput, UncompressedViewIntoTheDatalessFallbackBuffer) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    TempDir dir;
    const fs::path file = brokenMeshoptEngine(dir, [](nlohmann::json& document) {
        document["bufferViews"][0].erase("extensions");
    });
    expectLoadError(file, {"bufferViews[0]", "fallback buffer without data, but is not compressed"});
}

} // namespace

// --- small files with known contents, from the fuzz seeds' generators --------------------

namespace {

// The meshopt seed: a unit quad (after the node's dequantizing scale) in z = 0, normals +x,
// +y, +z, (0.6, 0, -0.8) through the OCTAHEDRAL filter, uv (0,0) (1,0) (1,1) (0,1) through the EXPONENTIAL filter,
// the same triangles once from a TRIANGLES stream and once from an INDICES stream.
TEST(GltfCompressedKnownContents, MeshoptQuadDecodesEveryModeAndFilter) {
    TempDir dir;
    gltf_writer::writeBytes(dir / "quad.glb", compressed_seeds::meshoptQuad().glbBytes());
    const engine::Scene scene = engine::loadGltf(dir / "quad.glb");
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].primitives.size(), 2u);
    const std::vector<glm::dvec3> corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<glm::vec3> normals = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.6f, 0, -0.8f}};
    for (const engine::Primitive& primitive : scene.meshes[0].primitives) {
        EXPECT_EQ(primitive.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
        ASSERT_EQ(primitive.positions.size(), 4u);
        for (std::size_t v = 0; v < 4; ++v) {
            const glm::dvec3 world = glm::dvec3(scene.meshInstances[0].world * glm::dvec4(glm::dvec3(primitive.positions[v]), 1.0));
            // 1023 * (1/1023) in float: exact to ~1e-7.
            EXPECT_LT(glm::length(world - corners[v]), 1e-6) << "vertex " << v;
            // 8-bit octahedral: x and y on a grid of step 2/254 (error <= 1/127 each), the
            // decoded vector rounded to 8 bits again (<= 0.5/127 per component): within 0.02.
            EXPECT_LT(glm::length(primitive.normals[v] - normals[v]), 0.02f) << "vertex " << v;
            // 15-bit mantissas hold 0 and 1 exactly.
            EXPECT_EQ(primitive.texcoords[v], uvs[v]) << "vertex " << v;
        }
    }
    EXPECT_NEAR(scene.worldBounds.max.x, 1.0, 1e-6);
}

// The Draco seed: a split-vertex unit cube, 12 triangles, positions quantized to 11 bits
// over the unit cube (step 1/2047: corners 0 and 1 are exact), 8-bit normals.
TEST(GltfCompressedKnownContents, DracoCubeDecodesToTheCube) {
    TempDir dir;
    gltf_writer::writeBytes(dir / "cube.glb", compressed_seeds::dracoCube().glbBytes());
    const engine::Scene scene = engine::loadGltf(dir / "cube.glb");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const engine::Primitive& primitive = scene.meshes[0].primitives.at(0);
    EXPECT_EQ(primitive.triangleCount(), 12u);
    for (std::size_t i = 0; i < primitive.indices.size(); ++i) {
        const glm::vec3& p = primitive.positions.at(primitive.indices[i]);
        for (int axis = 0; axis < 3; ++axis) EXPECT_TRUE(p[axis] == 0.0f || p[axis] == 1.0f) << "corner " << i;
        // 8-bit normals of axis directions: within one quantization step of the axis.
        const glm::vec3& n = primitive.normals.at(primitive.indices[i]);
        EXPECT_GT(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 0.99f) << "corner " << i;
    }
    EXPECT_TRUE(scene.meshes[0].closed);  // the split vertices weld by position
    EXPECT_EQ(scene.worldBounds.min, glm::dvec3(0.0));
    EXPECT_EQ(scene.worldBounds.max, glm::dvec3(1.0));
}

} // namespace
