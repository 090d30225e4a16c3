// The reversed-Z and forced-plane projections, the cube's reference depth and the offset
// clamp's depth per texel: the plugin's math behind the stress fixes, without GL.
#include "math/LightFrustum.h"
#include "math/Texgen.h"

#include "engine/scene/Scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
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

} // namespace
