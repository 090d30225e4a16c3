// The alpha-masked test scenes in content/scenes (tools/scripts/make_masked_scenes.py) load as
// authored, and each masked caster has the outline of its opaque twin: the twin is only a
// reference if it covers exactly the texels the mask keeps.
#include "engine/gltf/GltfLoader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace {

namespace fs = std::filesystem;

engine::Scene load(const std::string& name) { return engine::loadGltf(fs::path(CONTENT_DIR) / "scenes" / (name + ".gltf")); }

const engine::Mesh& meshNamed(const engine::Scene& scene, const std::string& name) {
    for (const engine::Mesh& mesh : scene.meshes)
        if (mesh.name == name) return mesh;
    throw std::runtime_error("no mesh " + name);
}

// Whether p lies inside triangle (a, b, c) of the XY plane (either winding).
bool insideTriangle(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const auto side = [](glm::vec2 o, glm::vec2 u, glm::vec2 v) { return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x); };
    const float d0 = side(a, b, p), d1 = side(b, c, p), d2 = side(c, a, p);
    return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

bool insideAnyTriangle(const engine::Primitive& primitive, glm::vec2 p) {
    for (std::size_t t = 0; t < primitive.indices.size(); t += 3)
        if (insideTriangle(p, glm::vec2(primitive.positions[primitive.indices[t]]),
                           glm::vec2(primitive.positions[primitive.indices[t + 1]]),
                           glm::vec2(primitive.positions[primitive.indices[t + 2]])))
            return true;
    return false;
}

void expectBinaryAlpha(const engine::Image& image) {
    for (std::size_t i = 3; i < image.rgba8.size(); i += 4)
        ASSERT_TRUE(image.rgba8[i] == 0 || image.rgba8[i] == 255) << image.name << " texel " << i / 4;
}

void expectMaskMaterial(const engine::Scene& scene, int index) {
    ASSERT_GE(index, 0);
    const engine::Material& material = scene.materials[index];
    EXPECT_EQ(material.alphaMode, engine::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(material.alphaCutoff, 0.5f);
    EXPECT_TRUE(material.doubleSided);
    EXPECT_TRUE(material.baseColorTexture.present());
}

void expectOpaqueDoubleSided(const engine::Scene& scene, int index) {
    ASSERT_GE(index, 0);
    const engine::Material& material = scene.materials[index];
    EXPECT_EQ(material.alphaMode, engine::AlphaMode::Opaque);
    EXPECT_TRUE(material.doubleSided);
    EXPECT_FALSE(material.baseColorTexture.present());
}

// The caster primitives (mesh `shape`) of a masked scene and its twin, each made of the
// material its role needs: masked and textured, or opaque.
std::pair<const engine::Primitive&, const engine::Primitive&> casters(const engine::Scene& masked,
                                                                     const engine::Scene& twin,
                                                                     const std::string& shape) {
    const engine::Primitive& maskedCaster = meshNamed(masked, shape).primitives.at(0);
    const engine::Primitive& twinCaster = meshNamed(twin, shape).primitives.at(0);
    expectMaskMaterial(masked, maskedCaster.material);
    expectOpaqueDoubleSided(twin, twinCaster.material);
    return {maskedCaster, twinCaster};
}

TEST(MaskedContent, FenceMaskKeepsExactlyTheTexelsItsTwinCovers) {
    const engine::Scene masked = load("masked_fence"), twin = load("opaque_fence");
    const auto [quad, slats] = casters(masked, twin, "fence");
    ASSERT_EQ(quad.triangleCount(), 2u);
    ASSERT_EQ(masked.images.size(), 1u);
    const engine::Image& image = masked.images[0];
    ASSERT_EQ(image.width, 96);
    ASSERT_EQ(image.height, 32);
    expectBinaryAlpha(image);
    // The quad spans x in [-3, 3], y in [0, 2] with u = (x + 3) / 6, v = (2 - y) / 2.
    ASSERT_EQ(quad.texcoords.size(), quad.positions.size());
    for (std::size_t i = 0; i < quad.positions.size(); ++i) {
        EXPECT_FLOAT_EQ(quad.texcoords[i].x, (quad.positions[i].x + 3.0f) / 6.0f);
        EXPECT_FLOAT_EQ(quad.texcoords[i].y, (2.0f - quad.positions[i].y) / 2.0f);
    }
    int opaque = 0;
    for (int row = 0; row < image.height; ++row)
        for (int column = 0; column < image.width; ++column) {
            const bool kept = image.rgba8[4 * (row * image.width + column) + 3] == 255;
            const glm::vec2 centre(-3.0f + (column + 0.5f) * 6.0f / 96.0f, 2.0f - (row + 0.5f) * 2.0f / 32.0f);
            EXPECT_EQ(kept, insideAnyTriangle(slats, centre)) << "texel column " << column << ", row " << row;
            opaque += kept;
        }
    EXPECT_GT(opaque, 96 * 32 / 3);  // slats and rails, not an empty or full mask
    EXPECT_LT(opaque, 96 * 32 * 2 / 3);
    // Every twin corner lies on a texel boundary of the plane z = 0.
    for (const glm::vec3& p : slats.positions) {
        EXPECT_FLOAT_EQ(p.z, 0.0f);
        const float column = (p.x + 3.0f) * 16.0f, row = (2.0f - p.y) * 16.0f;
        EXPECT_NEAR(column, std::round(column), 1e-4f);
        EXPECT_NEAR(row, std::round(row), 1e-4f);
    }
}

TEST(MaskedContent, CanopyLeavesAndTheirPolygonsShareCentreAndPlane) {
    const engine::Scene masked = load("masked_canopy"), twin = load("opaque_canopy");
    const auto [quads, fans] = casters(masked, twin, "canopy");
    ASSERT_EQ(masked.images.size(), 1u);
    EXPECT_EQ(masked.images[0].width, 64);
    EXPECT_EQ(masked.images[0].height, 64);
    expectBinaryAlpha(masked.images[0]);
    constexpr std::size_t kLeaves = 60, kSides = 24;
    ASSERT_EQ(quads.positions.size(), 4 * kLeaves);
    ASSERT_EQ(fans.positions.size(), (kSides + 1) * kLeaves);
    EXPECT_EQ(fans.triangleCount(), kSides * kLeaves);
    for (std::size_t leaf = 0; leaf < kLeaves; ++leaf) {
        const glm::vec3* corner = &quads.positions[4 * leaf];
        const glm::vec3 centre = (corner[0] + corner[1] + corner[2] + corner[3]) * 0.25f;
        EXPECT_LT(glm::length(fans.positions[(kSides + 1) * leaf] - centre), 1e-5f) << "leaf " << leaf;
        EXPECT_GE(centre.y, 2.5f);
        EXPECT_LE(centre.y, 3.0f);
        const glm::vec3 normal = glm::normalize(glm::cross(corner[1] - corner[0], corner[2] - corner[0]));
        for (std::size_t i = 1; i <= kSides; ++i)  // the polygon lies in the quad's plane
            EXPECT_NEAR(glm::dot(fans.positions[(kSides + 1) * leaf + i] - centre, normal), 0.0f, 1e-5f);
    }
}

TEST(MaskedContent, EverySceneHasItsNamedLightsAndCamera) {
    for (const char* name : {"masked_fence", "opaque_fence", "masked_canopy", "opaque_canopy"}) {
        SCOPED_TRACE(name);
        const engine::Scene scene = load(name);
        EXPECT_GE(scene.findCameraInstance("main_camera"), 0);
        const std::pair<const char*, engine::Light::Type> lights[] = {{"spot_light", engine::Light::Type::Spot},
                                                                      {"sun", engine::Light::Type::Directional},
                                                                      {"point_light", engine::Light::Type::Point}};
        for (const auto& [light, type] : lights) {
            const int instance = scene.findLightInstance(light);
            ASSERT_GE(instance, 0) << light;
            EXPECT_EQ(scene.lights[scene.lightInstances[instance].light].type, type) << light;
        }
        // The fence's lights stand behind it (z < 0), its camera in front.
        if (std::string(name).find("fence") != std::string::npos) {
            EXPECT_LT(scene.lightInstances[scene.findLightInstance("spot_light")].position().z, 0.0);
            EXPECT_LT(scene.lightInstances[scene.findLightInstance("point_light")].position().z, 0.0);
            EXPECT_GT(scene.cameraInstances[scene.findCameraInstance("main_camera")].world[3].z, 0.0);
        }
    }
}

// The loader on this branch does not read samplers yet: the files themselves must say
// LINEAR magnification, LINEAR_MIPMAP_LINEAR minification and CLAMP_TO_EDGE.
TEST(MaskedContent, MaskedScenesUseALinearMipmappedClampedSampler) {
    for (const char* name : {"masked_fence", "masked_canopy"}) {
        std::ifstream file(fs::path(CONTENT_DIR) / "scenes" / (std::string(name) + ".gltf"));
        const nlohmann::json gltf = nlohmann::json::parse(file);
        ASSERT_EQ(gltf.at("samplers").size(), 1u) << name;
        const nlohmann::json& sampler = gltf["samplers"][0];
        EXPECT_EQ(sampler.at("magFilter"), 9729) << name;  // LINEAR
        EXPECT_EQ(sampler.at("minFilter"), 9987) << name;  // LINEAR_MIPMAP_LINEAR
        EXPECT_EQ(sampler.at("wrapS"), 33071) << name;     // CLAMP_TO_EDGE
        EXPECT_EQ(sampler.at("wrapT"), 33071) << name;
        EXPECT_EQ(gltf["textures"][0].at("sampler"), 0) << name;
    }
}

} // namespace
