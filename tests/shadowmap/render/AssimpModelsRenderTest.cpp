// Models nobody here wrote: every glTF file Debian's assimp-testmodels ships either fails
// to load with an InputError (tested in tests/unit) or loads and then renders, with a key
// light of each type and the shadow plugin, without an exception or a GL error.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"
#include "../../support/AssimpTestModels.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/scene/SceneEdit.h"

#include <filesystem>

namespace {

class AssimpModels : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }
};

} // namespace

TEST_F(AssimpModels, EveryLoadableModelRendersWithShadows) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    int loaded = 0, rendered = 0, refused = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(engine::test::kAssimpGltf2Models)) {
        const std::string extension = entry.path().extension().string();
        if (!entry.is_regular_file() || (extension != ".gltf" && extension != ".glb")) continue;
        engine::Scene scene;
        try {
            scene = engine::loadGltf(entry.path());
        } catch (const engine::InputError&) {
            ++refused;
            continue;
        }
        ++loaded;
        engine::addKeyLight(scene, engine::Light::Type::Spot, "key_spot");
        engine::addKeyLight(scene, engine::Light::Type::Point, "key_point");
        engine::addKeyLight(scene, engine::Light::Type::Directional, "key_sun");
        SCOPED_TRACE(entry.path().string());
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = engine::framingCamera(scene, 48, 32);
        ASSERT_NO_THROW(renderer.renderFrame(request));
        ASSERT_NO_THROW(engine::gl::checkGlError("rendering an assimp model"));
        const auto pixels = renderer.readColor();
        ASSERT_EQ(pixels.size(), 48u * 32u * 4u);
        ++rendered;
    }
    std::printf("assimp glTF2 models: %d loaded and rendered, %d refused\n", rendered, refused);
    EXPECT_GE(loaded, 25);
    EXPECT_EQ(rendered, loaded);
}
