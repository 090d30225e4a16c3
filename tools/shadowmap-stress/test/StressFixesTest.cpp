// The fixes shadowmap-stress drove, checked through the plugin on one EGL context (their
// math, without GL, is tests/shadowmap/unit/ReversedDepthTest.cpp): the new settings are
// validated with one clear sentence, an infinite far plane is reported as such, a clamped
// cone and non-finite texgen planes are said out loud instead of shading with NaN.
#include "StressScenes.h"

#include "engine/context/GlContext.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "shadowmap/ShadowViewSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace {

// The skinned stress scenes really are posed through their skins (else distance_skinned
// would silently repeat distance), and land where the node-placed ones stand: a million
// units out, float positions relative to each pose's centre keep the corners within 1e-3
// (float spacing at the boxes' half-extents of a few units is below 1e-6; the double
// subtraction of the centre loses nothing).
TEST(SkinnedStressScene, EveryMeshIsPosedByItsSkinWhereTheNodePlacedOneStands) {
    stress::SceneSpec spec;
    spec.offset = glm::dvec3(0.6, 0.48, 0.64) * 1e6;
    const stress::StressScene placed = stress::buildStressScene(spec, 64, 48);
    spec.skinned = true;
    const stress::StressScene skinned = stress::buildStressScene(spec, 64, 48);
    ASSERT_EQ(placed.scene.meshInstances.size(), skinned.scene.meshInstances.size());
    for (std::size_t i = 0; i < placed.scene.meshInstances.size(); ++i) {
        const engine::MeshInstance& a = placed.scene.meshInstances[i];
        const engine::MeshInstance& b = skinned.scene.meshInstances[i];
        EXPECT_FALSE(a.deformed);
        ASSERT_TRUE(b.deformed) << "mesh " << i << " is not posed by a skin";
        EXPECT_EQ(b.world, glm::dmat4(1.0));  // a skinned mesh's vertices are in world space
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(b.worldBounds.min[axis], a.worldBounds.min[axis], 1e-3) << "mesh " << i;
            EXPECT_NEAR(b.worldBounds.max[axis], a.worldBounds.max[axis], 1e-3) << "mesh " << i;
        }
    }
}

// Through the plugin: one EGL context and the plugin for the whole suite.
class StressFixes : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = engine::createEglContext();
        context_->makeCurrent();
        host_ = std::make_unique<engine::PluginHost>();
        host_->load({shadowmap::kPluginName, nlohmann::json::object()}, {ENGINE_PLUGIN_DIR});
    }
    static void TearDownTestSuite() {
        host_.reset();  // the plugins' GL objects go while the context is current
        context_.reset();
    }

    // The light's shadow view after one frame of a generated scene with `shadow` on its
    // light; nothing (and the error message) when the settings are refused.
    static std::optional<engine::ShadowView> render(const nlohmann::json& shadow, std::string* error = nullptr,
                                 stress::LightKind kind = stress::LightKind::Spot,
                                 double outerCone = 0.0) {
        stress::SceneSpec spec;
        spec.light = kind;
        spec.shadow = shadow;
        stress::StressScene built = stress::buildStressScene(spec, 64, 48);
        if (outerCone > 0.0) built.scene.lights[0].outerConeAngle = outerCone;
        engine::Renderer renderer({}, host_->renderPlugins());
        try {
            renderer.setScene(built.scene);
        } catch (const engine::InputError& e) {
            if (error) *error = e.what();
            return std::nullopt;
        }
        engine::FrameRequest request;
        request.camera = built.camera;
        return renderer.renderFrame(request).shadowViews.at(0);
    }

    static inline std::unique_ptr<engine::GlContext> context_;
    static inline std::unique_ptr<engine::PluginHost> host_;
};

TEST_F(StressFixes, ReversedZNeedsD32f) {
    std::string error;
    render({{"reversed_z", true}, {"depth_format", "d24"}}, &error);
    EXPECT_NE(error.find("light \"light\""), std::string::npos) << error;
    EXPECT_NE(error.find("reversed_z"), std::string::npos) << error;
    EXPECT_NE(error.find("d32f"), std::string::npos) << error;
}

TEST_F(StressFixes, ForcedPlanesAreChecked) {
    std::string error;
    render({{"near_plane", -1.0}}, &error);
    EXPECT_NE(error.find("near_plane"), std::string::npos) << error;
    error.clear();
    render({{"near_plane", 5.0}, {"far_plane", 2.0}}, &error);
    EXPECT_NE(error.find("far_plane"), std::string::npos) << error;
    error.clear();
    render({{"far_plane", "far"}}, &error);
    EXPECT_NE(error.find("\"infinite\""), std::string::npos) << error;
    error.clear();
    render({{"polygon_offset_clamp", -1.0}}, &error);
    EXPECT_NE(error.find("polygon_offset_clamp"), std::string::npos) << error;
}

TEST_F(StressFixes, ReversedZRendersWithAnInfiniteFarAndSaysSo) {
    for (const stress::LightKind kind : {stress::LightKind::Spot, stress::LightKind::Point}) {
        const std::optional<engine::ShadowView> light =
            render({{"reversed_z", true}, {"depth_format", "d32f"}}, nullptr, kind);
        ASSERT_TRUE(light.has_value());
        EXPECT_TRUE(std::isinf(light->farPlane));
        EXPECT_TRUE(shadowmap::usedSettings(*light).reversedZ);
        EXPECT_TRUE(light->hasMap);
    }
}

TEST_F(StressFixes, ANearPlaneBeyondTheSceneLosesTheShadowLoudly) {
    testing::internal::CaptureStderr();
    const std::optional<engine::ShadowView> light = render({{"near_plane", 1000.0}});
    const std::string warnings = testing::internal::GetCapturedStderr();
    ASSERT_TRUE(light.has_value());
    EXPECT_FALSE(light->hasMap);
    EXPECT_NE(light->skipReason.find("degenerate"), std::string::npos) << light->skipReason;
    EXPECT_NE(warnings.find("light \"light\""), std::string::npos) << warnings;
}

TEST_F(StressFixes, NonFiniteTexgenPlanesLoseTheShadowWithAWarning) {
    // A spot cone of 1e-39 rad: cot(half angle) ~ 2e39 does not fit a float, so the eye
    // planes Ee would reach the GPU as Inf. The light must not shade with Inf/NaN; it
    // loses its shadow and says so.
    testing::internal::CaptureStderr();
    const std::optional<engine::ShadowView> light =
        render(nlohmann::json::object(), nullptr, stress::LightKind::Spot, 1e-39);
    const std::string warnings = testing::internal::GetCapturedStderr();
    ASSERT_TRUE(light.has_value());
    EXPECT_NE(warnings.find("texgen planes for this camera are not finite"), std::string::npos)
        << warnings << light->skipReason;
}

TEST_F(StressFixes, AConeTooWideForAPerspectiveMapIsClampedWithAWarning) {
    testing::internal::CaptureStderr();
    const std::optional<engine::ShadowView> light =
        render(nlohmann::json::object(), nullptr, stress::LightKind::Spot, 1.57);
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_NE(warnings.find("clamped to 89 deg"), std::string::npos) << warnings;
    ASSERT_TRUE(light.has_value());
    EXPECT_TRUE(light->hasMap);
}

} // namespace
