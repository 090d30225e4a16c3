// The fixes shadowmap-stress drove, checked directly: the reversed-Z and infinite
// projections and their texgen S (no GL), and through the plugin on one EGL context: the
// new settings are validated with one clear sentence, an infinite far plane is reported as
// such, a clamped cone and non-finite texgen planes are said out loud instead of shading
// with NaN.
#include "StressScenes.h"

#include "math/LightFrustum.h"
#include "math/Texgen.h"

#include "engine/context/GlContext.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace {

using shadowmap::FrustumFitOptions;
using shadowmap::LightView;

// A spot light at the origin looking down -Z over a receiver from depth 2 to 10.
LightView fitSpot(FrustumFitOptions options) {
    engine::LightInstance placed;  // identity: at the origin, shining down -Z
    engine::Light light;
    light.type = engine::Light::Type::Spot;
    light.outerConeAngle = 0.5;
    shadowmap::ShadowBounds bounds;
    bounds.receivers.push_back({{-0.5, -0.5, -10.0}, {0.5, 0.5, -2.0}});
    bounds.casters = bounds.receivers;
    return shadowmap::fitSpotLight(placed, light, bounds, options);
}

// r/q of the texgen planes (S P_light L^-1) at distance d along the light's axis.
double windowDepth(const LightView& view, double d) {
    const glm::dvec4 c = view.texgenPlanes() * glm::dvec4(0.0, 0.0, -d, 1.0);
    return c.z / c.w;
}

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

TEST(ReversedZ, PerspectiveMapsNearToOneAndFarToZero) {
    FrustumFitOptions options;
    options.reversedZ = true;
    options.nearPlane = 1.0;
    options.farPlane = 20.0;
    const LightView view = fitSpot(options);
    ASSERT_TRUE(view.valid) << view.invalidReason;
    EXPECT_NEAR(windowDepth(view, 1.0), 1.0, 1e-12);
    EXPECT_NEAR(windowDepth(view, 20.0), 0.0, 1e-12);
    // n (f - d) / ((f - n) d): the reversed [0,1] depth of the same projection.
    EXPECT_NEAR(windowDepth(view, 5.0), 1.0 * (20.0 - 5.0) / (19.0 * 5.0), 1e-12);
    // s and t keep the scale-bias: the axis lands in the middle of the map.
    const glm::dvec4 c = view.texgenPlanes() * glm::dvec4(0.0, 0.0, -5.0, 1.0);
    EXPECT_NEAR(c.x / c.w, 0.5, 1e-12);
    EXPECT_NEAR(c.y / c.w, 0.5, 1e-12);
}

TEST(ReversedZ, WithoutAForcedFarThePlaneIsInfiniteAndDepthIsNearOverDistance) {
    FrustumFitOptions options;
    options.reversedZ = true;
    options.nearPlane = 1e-6;
    const LightView view = fitSpot(options);
    ASSERT_TRUE(view.valid) << view.invalidReason;
    EXPECT_TRUE(std::isinf(view.farPlane));
    for (double d : {2.0, 7.0, 1e6}) {
        EXPECT_NEAR(windowDepth(view, d) / (1e-6 / d), 1.0, 1e-12) << d;
        // float keeps 2^-24 relative precision of n/d, whatever the ratio
        EXPECT_NEAR(static_cast<float>(windowDepth(view, d)) / (1e-6 / d), 1.0, 1e-7) << d;
    }
}

TEST(ForcedPlanes, InfiniteFarInTheOpenGLConventionAndNearBeyondFarIsDegenerate) {
    FrustumFitOptions options;
    options.nearPlane = 0.5;
    options.farPlane = std::numeric_limits<double>::infinity();
    const LightView infinite = fitSpot(options);
    ASSERT_TRUE(infinite.valid) << infinite.invalidReason;
    EXPECT_NEAR(windowDepth(infinite, 0.5), 0.0, 1e-12);
    EXPECT_NEAR(windowDepth(infinite, 4.0), 1.0 - 0.5 / 4.0, 1e-12);

    options.nearPlane = 30.0;  // beyond everything: no usable frustum, never NaN
    options.farPlane = 20.0;
    const LightView degenerate = fitSpot(options);
    EXPECT_FALSE(degenerate.valid);
    EXPECT_NE(degenerate.invalidReason.find("degenerate"), std::string::npos) << degenerate.invalidReason;
}

TEST(ReversedZ, CubeReferenceDepthMatchesTheFaceProjection) {
    const double n = 0.1, f = 50.0;
    for (const bool reversed : {false, true}) {
        FrustumFitOptions options;
        options.reversedZ = reversed;
        options.nearPlane = n;
        options.farPlane = f;
        engine::LightInstance placed;
        engine::Light light;
        light.type = engine::Light::Type::Point;
        shadowmap::ShadowBounds bounds;
        bounds.receivers.push_back({{-5, -5, -5}, {5, 5, 5}});
        const shadowmap::PointLightViews views = shadowmap::fitPointLight(placed, light, bounds, options);
        ASSERT_TRUE(views.valid);
        const glm::dvec3 p(1.0, -7.0, 2.5);  // major axis -Y: face 3
        const glm::dvec4 c = shadowmap::scaleBiasZeroToOne() * views.faces[3].viewProjection() * glm::dvec4(p, 1.0);
        const double projected = reversed ? c.z / c.w : 0.5 * (c.z / c.w) + 0.5;
        EXPECT_NEAR(shadowmap::cubeShadowReferenceDepth(p, n, f, reversed), projected, 1e-12) << reversed;
    }
}

TEST(OffsetClamp, WindowDepthPerTexelOfAnOrthographicMapIsTexelOverDepthRange) {
    LightView view;
    view.projection = glm::orthoRH_NO(-4.0, 4.0, -4.0, 4.0, 0.0, 16.0);
    view.nearPlane = 0.0;
    view.farPlane = 16.0;
    // texel 8/1024 world units; a 45-degree surface changes depth by as much per texel
    EXPECT_NEAR(shadowmap::windowDepthPerTexel(view, 1024), (8.0 / 1024.0) / 16.0, 1e-15);
    // scale-free: the same map of a scene ten times larger
    view.projection = glm::orthoRH_NO(-40.0, 40.0, -40.0, 40.0, 0.0, 160.0);
    view.farPlane = 160.0;
    EXPECT_NEAR(shadowmap::windowDepthPerTexel(view, 1024), (8.0 / 1024.0) / 16.0, 1e-15);
}

// Through the plugin: one EGL context and the plugin for the whole suite.
class StressFixes : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = engine::createEglContext();
        context_->makeCurrent();
        host_ = std::make_unique<engine::PluginHost>();
        host_->load({"shadowmap_plugin", nlohmann::json::object()}, {ENGINE_PLUGIN_DIR});
    }
    static void TearDownTestSuite() {
        host_.reset();  // the plugins' GL objects go while the context is current
        context_.reset();
    }

    // The light's stats after one frame of a generated scene with `shadow` on its light;
    // the error message instead when the settings are refused.
    static nlohmann::json render(const nlohmann::json& shadow, std::string* error = nullptr,
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
            return nullptr;
        }
        engine::FrameRequest request;
        request.camera = built.camera;
        return renderer.renderFrame(request).pluginStats["shadowmap_plugin"]["lights"][0];
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
        const nlohmann::json light = render({{"reversed_z", true}, {"depth_format", "d32f"}}, nullptr, kind);
        ASSERT_TRUE(light.is_object());
        EXPECT_EQ(light["far"], "infinite");
        EXPECT_EQ(light["reversed_z"], true);
        EXPECT_NE(light["map"], "none");
    }
}

TEST_F(StressFixes, ANearPlaneBeyondTheSceneLosesTheShadowLoudly) {
    testing::internal::CaptureStderr();
    const nlohmann::json light = render({{"near_plane", 1000.0}});
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_EQ(light["map"], "none");
    EXPECT_NE(light.value("skip_reason", "").find("degenerate"), std::string::npos) << light.dump();
    EXPECT_NE(warnings.find("light \"light\""), std::string::npos) << warnings;
}

TEST_F(StressFixes, NonFiniteTexgenPlanesLoseTheShadowWithAWarning) {
    // A spot cone of 1e-39 rad: cot(half angle) ~ 2e39 does not fit a float, so the eye
    // planes Ee would reach the GPU as Inf. The light must not shade with Inf/NaN; it
    // loses its shadow and says so.
    testing::internal::CaptureStderr();
    const nlohmann::json light = render(nlohmann::json::object(), nullptr, stress::LightKind::Spot, 1e-39);
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_NE(warnings.find("texgen planes for this camera are not finite"), std::string::npos)
        << warnings << light.dump();
}

TEST_F(StressFixes, AConeTooWideForAPerspectiveMapIsClampedWithAWarning) {
    testing::internal::CaptureStderr();
    const nlohmann::json light = render(nlohmann::json::object(), nullptr, stress::LightKind::Spot, 1.57);
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_NE(warnings.find("clamped to 89 deg"), std::string::npos) << warnings;
    EXPECT_NE(light["map"], "none");
}

} // namespace
