// Models nobody here wrote: every glTF file Debian's assimp-testmodels ships either fails
// to load with an InputError (tested in tests/unit) or loads and then renders, with a key
// light of each type and the shadow plugin, without an exception or a GL error.
#include "../../gl/GlTestContext.h"
#include "AnalyticShadows.h"
#include "../../support/AssimpTestModels.h"

#include "engine/gltf/GltfLoader.h"
#include "engine/render/CameraSetup.h"
#include "engine/scene/SceneEdit.h"
#include "engine/scene/SceneNames.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

class AssimpModels : public engine::test::ShadowPluginTest {
protected:
    static void SetUpTestSuite() { loadPlugin({{"resolution", 256}}); }
};

// Calls visit(file, scene) for every glTF file of assimp-testmodels the loader accepts;
// returns how many it refused (each with an InputError, tested in tests/unit).
template <typename Visit>
int forEachLoadableModel(Visit visit) {
    int refused = 0;
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
        visit(entry.path(), scene);
    }
    return refused;
}

} // namespace

TEST_F(AssimpModels, EveryLoadableModelRendersWithShadows) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    int loaded = 0, rendered = 0;
    const int refused = forEachLoadableModel([&](const std::filesystem::path& file, engine::Scene& scene) {
        ++loaded;
        engine::addKeyLight(scene, engine::Light::Type::Spot, "key_spot");
        engine::addKeyLight(scene, engine::Light::Type::Point, "key_point");
        engine::addKeyLight(scene, engine::Light::Type::Directional, "key_sun");
        SCOPED_TRACE(file.string());
        engine::Renderer renderer({}, plugins());
        renderer.setScene(scene);
        engine::FrameRequest request;
        request.camera = engine::framingCamera(scene, 48, 32);
        ASSERT_NO_THROW(renderer.renderFrame(request));
        ASSERT_NO_THROW(engine::gl::checkGlError("rendering an assimp model"));
        const auto pixels = renderer.readColor();
        ASSERT_EQ(pixels.size(), 48u * 32u * 4u);
        ++rendered;
    });
    std::printf("assimp glTF2 models: %d loaded and rendered, %d refused\n", rendered, refused);
    EXPECT_GE(loaded, 25);
    EXPECT_EQ(rendered, loaded);
}

// --key-light with --ground (tools/common/SceneLighting.h) is there to show a model's shadow,
// so the shadow must not hide behind the model: seen from the framing camera the tools then
// use, part of the ground the camera sees past the model's bounds lies in the key light's
// shadow, for every light type and every model that can show one. Two kinds cannot: a model
// flatter than 5 % of its width lies on the ground and shadows only what is under it, and
// Cameras.gltf is one quad standing on the ground leaning away from the camera, whose
// shadow from any light on the camera's side lies under the quad itself.
TEST_F(AssimpModels, TheKeyLightsShadowFallsOnGroundTheFramingCameraSees) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    constexpr int kWidth = 64, kHeight = 48;
    int checked = 0;
    std::vector<std::string> hidden;
    forEachLoadableModel([&](const std::filesystem::path& file, const engine::Scene& loaded) {
        const engine::Aabb model = loaded.worldBounds;
        if (model.empty()) return;
        const glm::dvec3 extent = model.extent();
        if (extent.y < 0.05 * std::max(extent.x, extent.z) || file.filename() == "Cameras.gltf") return;
        for (const auto type : {engine::Light::Type::Spot, engine::Light::Type::Point, engine::Light::Type::Directional}) {
            engine::Scene scene = loaded;
            engine::addKeyLight(scene, type);
            engine::addGround(scene);
            const engine::Aabb ground = scene.meshInstances.back().worldBounds;
            const engine::FrameCamera camera = engine::framingCamera(scene, kWidth, kHeight);
            const std::vector<std::uint8_t> mask =
                engine::test::renderShadowMask(plugins(), scene, camera, scene.findLightInstance("key_light"));
            int seen = 0, shadowed = 0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x) {
                    const engine::test::Ray ray = engine::test::pixelRay(camera, x, y);
                    if (ray.direction.y >= 0.0) continue;
                    const double t = (ground.max.y - ray.origin.y) / ray.direction.y;
                    const glm::dvec3 p = ray.origin + ray.direction * t;
                    if (p.x < ground.min.x || p.x > ground.max.x || p.z < ground.min.z || p.z > ground.max.z) continue;
                    double t0 = 0.0, t1 = 0.0;
                    if (engine::test::intersectBox(ray.origin, ray.direction, model, t0, t1) && t0 < t) continue;
                    ++seen;
                    shadowed += mask[y * kWidth + x] < 128;
                }
            ++checked;
            // At least 1 % of the ground in view: a shadow a user sees, not a stray pixel.
            if (shadowed * 100 < seen || shadowed < 4)
                hidden.push_back(file.filename().string() + " " + engine::toString(type) + ": " +
                                 std::to_string(shadowed) + " of " + std::to_string(seen) + " ground pixels");
        }
    });
    std::printf("key light shadows checked: %d (model, light type) pairs, %zu hidden\n", checked, hidden.size());
    EXPECT_GE(checked, 3 * 20);
    std::string list;
    for (const std::string& line : hidden) list += "\n  " + line;
    EXPECT_TRUE(hidden.empty()) << "shadow not in view:" << list;
}
