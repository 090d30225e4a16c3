// The plugin's shadow masks do not depend on the lit pass's BRDF: the showcase rendered
// with its own materials and with every material's base color, metallic and roughness
// changed gives byte-equal masks for every light, while the shaded image changes (so the
// material edit reached the shading and the comparison is not vacuous). The mask view and
// the shaded image share lit.frag; this pins that only the shaded path reads the material.
// Likewise for the surface textures (metallic-roughness, normal, occlusion, emissive): the
// normal map turns the shading normal only, never the normal the shadow lookup uses.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"

namespace {

constexpr int kWidth = 160, kHeight = 120;

// A 4x4 image of varied texels (every channel moves), for every surface texture.
engine::Image variedImage() {
    engine::Image image;
    image.width = image.height = 4;
    for (int i = 0; i < 16; ++i)
        image.rgba8.insert(image.rgba8.end(), {static_cast<std::uint8_t>(40 + i * 13), static_cast<std::uint8_t>(250 - i * 11),
                                               static_cast<std::uint8_t>(120 + (i * 37) % 120), 255});
    return image;
}

// Every material of `scene` given every surface texture, and every primitive UVs (from
// its x and z) and tangents (any unit vector across its normal), so each texture varies
// over each surface.
void addSurfaceTextures(engine::Scene& scene) {
    scene.images.push_back(variedImage());
    const int image = static_cast<int>(scene.images.size()) - 1;
    for (engine::Material& material : scene.materials)
        for (engine::TextureRef* slot : {&material.metallicRoughnessTexture, &material.normalTexture,
                                         &material.occlusionTexture, &material.emissiveTexture}) {
            slot->image = image;
            slot->sampler.minFilter = slot->sampler.magFilter = 0x2600;  // GL_NEAREST
        }
    for (engine::Material& material : scene.materials) material.emissiveFactor = glm::vec3(0.3f);
    for (engine::Mesh& mesh : scene.meshes)
        for (engine::Primitive& primitive : mesh.primitives) {
            primitive.texcoords.clear();
            primitive.tangents.clear();
            for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
                const glm::vec3 p = primitive.positions[v], n = primitive.normals[v];
                primitive.texcoords.push_back(glm::vec2(p.x, p.z) * 0.7f);
                const glm::vec3 across = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
                primitive.tangents.push_back(glm::vec4(glm::normalize(glm::cross(n, across)), 1.0f));
            }
        }
}

struct Rendered {
    std::vector<std::uint8_t> color;
    std::vector<std::vector<std::uint8_t>> masks;  // one per light slot
};

class MaskIgnoresBrdf : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 1024}}); }

    static Rendered render(engine::Scene scene) {
        scene.updateWorldTransforms();
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = engine::chooseCamera(scene, "", kWidth, kHeight, "showcase.gltf");
        for (int slot = 0; slot < static_cast<int>(scene.lightInstances.size()); ++slot)
            request.shadowMaskSlots.push_back(slot);
        renderer.renderFrame(request);
        Rendered rendered{renderer.readColor(), {}};
        for (const int slot : request.shadowMaskSlots) rendered.masks.push_back(renderer.readShadowMask(slot));
        return rendered;
    }
};

} // namespace

TEST_F(MaskIgnoresBrdf, ShowcaseMasksAreByteEqualWhateverTheMaterials) {
    const engine::Scene authored = engine::loadGltf(std::string(CONTENT_DIR) + "/scenes/showcase.gltf");
    engine::Scene edited = authored;
    for (engine::Material& material : edited.materials) {
        material.baseColorFactor = glm::vec4(0.2f, 0.9f, 0.5f, material.baseColorFactor.a);
        material.metallicFactor = 1.0f - material.metallicFactor;
        material.roughnessFactor = 0.1f;
    }
    const Rendered before = render(authored), after = render(edited);
    ASSERT_EQ(before.masks.size(), 3u);  // the showcase's spot, sun and point light
    ASSERT_EQ(before.masks.size(), after.masks.size());
    for (std::size_t slot = 0; slot < before.masks.size(); ++slot) {
        ASSERT_EQ(before.masks[slot].size(), std::size_t{kWidth} * kHeight);
        // A mask with both states present, so equality says something about shadows.
        int lit = 0, shadowed = 0;
        for (const std::uint8_t value : before.masks[slot]) (value > 127 ? lit : shadowed) += 1;
        EXPECT_GT(lit, 0) << "light slot " << slot;
        EXPECT_GT(shadowed, 0) << "light slot " << slot;
        EXPECT_TRUE(before.masks[slot] == after.masks[slot]) << "light slot " << slot << ": mask changed with the materials";
    }
    EXPECT_NE(before.color, after.color);
}

TEST_F(MaskIgnoresBrdf, ShowcaseMasksAreByteEqualWithEverySurfaceTexture) {
    const engine::Scene authored = engine::loadGltf(std::string(CONTENT_DIR) + "/scenes/showcase.gltf");
    engine::Scene textured = authored;
    addSurfaceTextures(textured);
    const Rendered before = render(authored), after = render(textured);
    ASSERT_EQ(before.masks.size(), 3u);
    for (std::size_t slot = 0; slot < before.masks.size(); ++slot)
        EXPECT_TRUE(before.masks[slot] == after.masks[slot]) << "light slot " << slot << ": mask changed with the textures";
    // The textures reached the shading: a large share of the image changed.
    std::size_t changed = 0;
    for (std::size_t i = 0; i < before.color.size(); ++i) changed += before.color[i] != after.color[i];
    EXPECT_GT(changed, before.color.size() / 4);
}
