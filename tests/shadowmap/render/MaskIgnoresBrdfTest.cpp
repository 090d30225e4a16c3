// The plugin's shadow masks do not depend on the lit pass's BRDF: the showcase rendered
// with its own materials and with every material's base color, metallic and roughness
// changed gives byte-equal masks for every light, while the shaded image changes (so the
// material edit reached the shading and the comparison is not vacuous). The mask view and
// the shaded image share lit.frag; this pins that only the shaded path reads the material.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"

namespace {

constexpr int kWidth = 160, kHeight = 120;

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
