// Light frusta fitted to casters and receivers: what the light must see lands inside the
// map (S P L^-1 in [0,1]^3), precision is not wasted on geometry outside the cone, cube
// faces follow the OpenGL cube-map table, and degenerate lights are reported, not NaN.
#include "math/LightFrustum.h"
#include "math/Texgen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

namespace {

using engine::Aabb;
using shadowmap::ShadowBounds;

Aabb box(glm::dvec3 a, glm::dvec3 b) {
    Aabb out;
    out.extend(a);
    out.extend(b);
    return out;
}

Aabb moved(const Aabb& b, const glm::dvec3& T) {
    return box(b.min + T, b.max + T);
}

engine::Light makeLight(engine::Light::Type type, double outer = 0.5, double range = 0.0) {
    engine::Light l;
    l.type = type;
    l.outerConeAngle = outer;
    l.range = range;
    return l;
}

// A light node at `position` shining toward `target` (glTF: lights shine down -Z).
engine::LightInstance lightAt(const glm::dvec3& position, const glm::dvec3& target) {
    glm::dvec3 up(0, 1, 0);
    if (glm::length(glm::cross(glm::normalize(target - position), up)) < 1e-3) up = {1, 0, 0};
    engine::LightInstance li;
    li.world = glm::inverse(glm::lookAtRH(position, target, up));
    li.world[3] = glm::dvec4(position, 1.0);
    return li;
}

// A node rotated -90 deg about X: its -Z points straight down, as glTF exporters write it.
engine::LightInstance lightStraightDown(const glm::dvec3& position) {
    engine::LightInstance li;
    li.world = glm::translate(glm::dmat4(1.0), position) *
               glm::rotate(glm::dmat4(1.0), -glm::half_pi<double>(), glm::dvec3(1, 0, 0));
    return li;
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

glm::dvec3 mapCoords(const shadowmap::LightView& v, const glm::dvec3& world) {
    const glm::dvec4 c = v.texgenPlanes() * glm::dvec4(world, 1.0);
    return glm::dvec3(c) / c.w;
}

// A floor much larger than any cone, some receivers on it, casters floating above.
ShadowBounds sceneBounds(std::mt19937_64& gen, const glm::dvec3& T = glm::dvec3(0.0)) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ShadowBounds b;
    b.receivers.push_back(moved(box({-1000, -0.5, -1000}, {1000, 0, 1000}), T));
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 c(4 * u(gen), 0.5 + 0.4 * u(gen), 4 * u(gen));
        b.receivers.push_back(moved(box(c - 0.5, c + 0.5), T));
        b.casters.push_back(b.receivers.back());
    }
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 c(3 * u(gen), 5 + 2 * u(gen), 3 * u(gen));
        b.casters.push_back(moved(box(c - 0.3, c + 0.3), T));
    }
    return b;
}

// --- Spot ----------------------------------------------------------------------------------

TEST(SpotLightFrustum, NearFarBracketEveryCornerInTheCone) {
    std::mt19937_64 gen(7);
    const ShadowBounds bounds = sceneBounds(gen);
    const engine::Light light = makeLight(engine::Light::Type::Spot, 0.5);
    const engine::LightInstance li = lightAt({1, 10, 2}, {0, 0, 0});
    const shadowmap::LightView v = shadowmap::fitSpotLight(li, light, bounds);
    ASSERT_TRUE(v.valid) << v.invalidReason;
    EXPECT_FALSE(v.empty);

    const glm::dvec3 p = li.position(), dir = li.direction();
    const glm::dmat4 toLight = glm::inverse(v.lightToWorld);
    int checked = 0;
    auto check = [&](const Aabb& b, bool receiver) {
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 w = b.corner(i);
            const double angle = std::acos(glm::dot(glm::normalize(w - p), dir));
            if (angle > light.outerConeAngle) continue;
            const double depth = -(toLight * glm::dvec4(w, 1.0)).z;
            EXPECT_GE(depth, v.nearPlane) << "corner " << i;
            if (receiver) {
                EXPECT_LE(depth, v.farPlane) << "corner " << i;
                const glm::dvec3 st = mapCoords(v, w);
                for (int k = 0; k < 3; ++k) {
                    EXPECT_GE(st[k], 0.0);
                    EXPECT_LE(st[k], 1.0);
                }
            }
            ++checked;
        }
    };
    for (const Aabb& b : bounds.receivers) check(b, true);
    for (const Aabb& b : bounds.casters) check(b, false);
    EXPECT_GT(checked, 40);
    // The floor's far corners are ~1000 away but outside the cone: far follows the cone's
    // footprint on the floor (< 15 here), and near the highest caster (~3 below the light).
    EXPECT_LT(v.farPlane, 15.0);
    EXPECT_GT(v.nearPlane, 2.0);
    EXPECT_LT(v.nearPlane, 5.0);
}

TEST(SpotLightFrustum, StraightDownIsFiniteAndTight) {
    const engine::Light light = makeLight(engine::Light::Type::Spot, 0.4);
    ShadowBounds bounds;
    bounds.receivers.push_back(box({-1000, -0.5, -1000}, {1000, 0, 1000}));
    const shadowmap::LightView v =
        shadowmap::fitSpotLight(lightStraightDown({0, 10, 0}), light, bounds);
    ASSERT_TRUE(v.valid) << v.invalidReason;
    EXPECT_TRUE(finite(v.lightToWorld));
    EXPECT_TRUE(finite(v.projection));
    EXPECT_TRUE(finite(v.texgenPlanes()));
    EXPECT_NEAR(v.lightToWorld[2].y, 1.0, 1e-15);  // light +Z = world up: looks down
    // The floor top is at depth 10, its bottom at 10.5 (depth is along the axis).
    EXPECT_GE(v.farPlane, 10.5);
    EXPECT_LT(v.farPlane, 10.6);
    EXPECT_LE(v.nearPlane, 10.0);
    EXPECT_GT(v.nearPlane, 9.9);
}

TEST(SpotLightFrustum, EveryAxisDirectionIsFinite) {
    const engine::Light light = makeLight(engine::Light::Type::Spot, 0.6);
    ShadowBounds bounds;
    bounds.receivers.push_back(box({-50, -50, -50}, {50, 50, 50}));
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            glm::dvec3 target(0.0);
            target[axis] = sign;
            const shadowmap::LightView v =
                shadowmap::fitSpotLight(lightAt({0, 0, 0}, target), light, bounds);
            ASSERT_TRUE(v.valid) << v.invalidReason;
            EXPECT_TRUE(finite(v.texgenPlanes()));
            EXPECT_GT(v.farPlane, 49.0);  // the box around the light: the near clamp holds
            EXPECT_NEAR(v.nearPlane, v.farPlane * 1e-4, 1e-12 * v.farPlane);
        }
}

TEST(SpotLightFrustum, RangeClampsFarAndEmptyConeIsReported) {
    std::mt19937_64 gen(3);
    const ShadowBounds bounds = sceneBounds(gen);
    const engine::LightInstance li = lightStraightDown({0, 10, 0});
    // The receiver boxes' tops are 8.6 to 9.4 below the light, the floor 10.
    const shadowmap::LightView ranged =
        shadowmap::fitSpotLight(li, makeLight(engine::Light::Type::Spot, 0.5, 9.5), bounds);
    ASSERT_TRUE(ranged.valid) << ranged.invalidReason;
    EXPECT_LE(ranged.farPlane, 9.5 * 1.001 + 1e-12);
    EXPECT_FALSE(ranged.empty);
    // Everything beyond the range: nothing receives this light, the pass can be skipped.
    const shadowmap::LightView short_ =
        shadowmap::fitSpotLight(li, makeLight(engine::Light::Type::Spot, 0.5, 8.0), bounds);
    EXPECT_TRUE(short_.valid);
    EXPECT_TRUE(short_.empty);

    // Pointing up at nothing: valid, finite, and empty so the pass can be skipped.
    const shadowmap::LightView up = shadowmap::fitSpotLight(
        lightAt({0, 10, 0}, {0, 20, 0}), makeLight(engine::Light::Type::Spot), bounds);
    EXPECT_TRUE(up.valid);
    EXPECT_TRUE(up.empty);
    EXPECT_TRUE(finite(up.projection));
}

TEST(SpotLightFrustum, FarFromOriginFitsTheSame) {
    const engine::Light light = makeLight(engine::Light::Type::Spot, 0.5);
    for (double d : {1e6, 1e7}) {
        std::mt19937_64 g0(11), g1(11);
        const glm::dvec3 T(d, 0.25 * d, -0.5 * d);
        const shadowmap::LightView a =
            shadowmap::fitSpotLight(lightAt({1, 10, 2}, {0, 0, 0}), light, sceneBounds(g0));
        const shadowmap::LightView b = shadowmap::fitSpotLight(lightAt(glm::dvec3(1, 10, 2) + T, T),
                                                               light, sceneBounds(g1, T));
        ASSERT_TRUE(b.valid) << b.invalidReason;
        EXPECT_NEAR(a.nearPlane, b.nearPlane, 1e-6 * a.nearPlane);
        EXPECT_NEAR(a.farPlane, b.farPlane, 1e-6 * a.farPlane);
    }
}

// --- Degenerate lights -----------------------------------------------------------------------

TEST(LightFrustumDegenerate, ZeroDirectionOrNaNPositionIsInvalidWithReason) {
    std::mt19937_64 gen(5);
    const ShadowBounds bounds = sceneBounds(gen);
    const double nan = std::numeric_limits<double>::quiet_NaN();

    engine::LightInstance flat = lightStraightDown({0, 10, 0});
    flat.world = flat.world * glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, 0));  // -Z = 0
    const shadowmap::LightView spotFlat =
        shadowmap::fitSpotLight(flat, makeLight(engine::Light::Type::Spot), bounds);
    EXPECT_FALSE(spotFlat.valid);
    EXPECT_NE(spotFlat.invalidReason.find("direction"), std::string::npos)
        << spotFlat.invalidReason;
    const shadowmap::LightView dirFlat =
        shadowmap::fitDirectionalLight(flat, makeLight(engine::Light::Type::Directional), bounds);
    EXPECT_FALSE(dirFlat.valid);
    EXPECT_FALSE(dirFlat.invalidReason.empty());

    engine::LightInstance lost = lightStraightDown({0, 10, 0});
    lost.world[3] = glm::dvec4(nan, 1, 2, 1);
    const shadowmap::LightView spotLost =
        shadowmap::fitSpotLight(lost, makeLight(engine::Light::Type::Spot), bounds);
    EXPECT_FALSE(spotLost.valid);
    EXPECT_NE(spotLost.invalidReason.find("position"), std::string::npos) << spotLost.invalidReason;
    const shadowmap::PointLightViews pointLost =
        shadowmap::fitPointLight(lost, makeLight(engine::Light::Type::Point), bounds);
    EXPECT_FALSE(pointLost.valid);
    EXPECT_FALSE(pointLost.invalidReason.empty());
    EXPECT_FALSE(pointLost.faceSeesBox(shadowmap::NegativeY, bounds.receivers[0]));

    // A directional light has no position: a NaN there changes nothing.
    const shadowmap::LightView dirLost =
        shadowmap::fitDirectionalLight(lost, makeLight(engine::Light::Type::Directional), bounds);
    EXPECT_TRUE(dirLost.valid) << dirLost.invalidReason;

    engine::Light noCone = makeLight(engine::Light::Type::Spot, 0.0);
    EXPECT_FALSE(shadowmap::fitSpotLight(lightStraightDown({0, 10, 0}), noCone, bounds).valid);

    // Infinite bounds are ignored, never turned into an infinite frustum.
    ShadowBounds bad = bounds;
    bad.receivers.push_back(box({-1, -1, -1}, {1, std::numeric_limits<double>::infinity(), 1}));
    const shadowmap::LightView spotBad = shadowmap::fitSpotLight(
        lightStraightDown({0, 10, 0}), makeLight(engine::Light::Type::Spot), bad);
    EXPECT_TRUE(spotBad.valid);
    EXPECT_TRUE(finite(spotBad.projection));
}

// --- Directional -----------------------------------------------------------------------------

ShadowBounds directionalBounds(const glm::dvec3& T) {
    ShadowBounds b;
    b.receivers.push_back(moved(box({-20, -0.5, -20}, {20, 0, 20}), T));
    b.receivers.push_back(moved(box({2, 0, 2}, {4, 3, 5}), T));
    b.casters = b.receivers;
    b.casters.push_back(moved(box({-3, 8, -2}, {-1, 12, 1}), T));  // above the floor
    // High up, but far off to the side: its shadow falls nowhere near the receivers.
    b.casters.push_back(moved(box({400, 900, 400}, {410, 910, 410}), T));
    return b;
}

void expectReceiversInsideMap(const shadowmap::LightView& v, const ShadowBounds& b) {
    for (const Aabb& r : b.receivers)
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 st = mapCoords(v, r.corner(i));
            for (int k = 0; k < 3; ++k) {
                EXPECT_GT(st[k], 0.0) << "corner " << i << " coord " << k;
                EXPECT_LT(st[k], 1.0) << "corner " << i << " coord " << k;
            }
        }
}

TEST(DirectionalLightFrustum, ReceiversInsideMapAndCastersTowardTheLight) {
    const ShadowBounds b = directionalBounds(glm::dvec3(0.0));
    engine::LightInstance li = lightAt({50, 80, 30}, {50 + 0.3, 80 - 1.0, 30 + 0.2});
    const shadowmap::LightView v =
        shadowmap::fitDirectionalLight(li, makeLight(engine::Light::Type::Directional), b);
    ASSERT_TRUE(v.valid) << v.invalidReason;
    EXPECT_FALSE(v.empty);
    expectReceiversInsideMap(v, b);
    // The caster above the floor is in depth range (r in [0,1]); the off-side one did not
    // stretch the depth range toward the light (it is ~900 up; the scene is ~13 high).
    for (int i = 0; i < 8; ++i) {
        const double r = mapCoords(v, b.casters[b.casters.size() - 2].corner(i)).z;
        EXPECT_GE(r, 0.0);
        EXPECT_LE(r, 1.0);
    }
    EXPECT_LT(v.farPlane, 40.0);
    // L sits near the scene, not at the node's position (only the direction matters).
    EXPECT_LT(glm::length(glm::dvec3(v.lightToWorld[3])), 40.0);
    EXPECT_NEAR(glm::dot(-glm::dvec3(v.lightToWorld[2]), li.direction()), 1.0, 1e-12);
}

TEST(DirectionalLightFrustum, StraightDownAndFarFromOrigin) {
    for (double d : {0.0, 1e6, 1e7}) {
        const glm::dvec3 T(d, -0.5 * d, 0.25 * d);
        const ShadowBounds b = directionalBounds(T);
        const shadowmap::LightView v = shadowmap::fitDirectionalLight(
            lightStraightDown({-7, 3, 9}), makeLight(engine::Light::Type::Directional), b);
        ASSERT_TRUE(v.valid) << v.invalidReason;
        EXPECT_TRUE(finite(v.texgenPlanes()));
        expectReceiversInsideMap(v, b);
        // Floor (40 x 40) + caster top at 12: the box is just that, whatever T is.
        EXPECT_NEAR(v.farPlane, 12.5, 0.1);
        EXPECT_NEAR(2.0 / v.projection[0][0], 40.0, 0.1);
    }
}

TEST(DirectionalLightFrustum, NoReceiversIsEmptyButFinite) {
    ShadowBounds b;
    b.casters.push_back(box({0, 0, 0}, {1, 1, 1}));
    const shadowmap::LightView v = shadowmap::fitDirectionalLight(
        lightStraightDown({0, 0, 0}), makeLight(engine::Light::Type::Directional), b);
    EXPECT_TRUE(v.valid);
    EXPECT_TRUE(v.empty);
    EXPECT_TRUE(finite(v.projection));
}

// --- Point ---------------------------------------------------------------------------------

TEST(PointLightFrustum, FloorBelowIsSeenByNegativeYOnly) {
    ShadowBounds b;
    b.receivers.push_back(box({-3, -1, -3}, {3, 0, 3}));
    engine::LightInstance li;
    li.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 5, 0));
    const shadowmap::PointLightViews v =
        shadowmap::fitPointLight(li, makeLight(engine::Light::Type::Point), b);
    ASSERT_TRUE(v.valid) << v.invalidReason;
    EXPECT_TRUE(v.faceSeesBox(shadowmap::NegativeY, b.receivers[0]));
    EXPECT_FALSE(v.faceSeesBox(shadowmap::PositiveY, b.receivers[0]));
    EXPECT_FALSE(v.faces[shadowmap::NegativeY].empty);
    for (int f : {shadowmap::PositiveX, shadowmap::NegativeX, shadowmap::PositiveY,
                  shadowmap::PositiveZ, shadowmap::NegativeZ})
        EXPECT_TRUE(v.faces[f].empty) << "face " << f;  // the floor is within 31 deg of -Y
    EXPECT_GE(v.farPlane, 6.0);
    EXPECT_LT(v.farPlane, 6.1);
    EXPECT_LE(v.nearPlane, 5.0);
}

// With direction r = world - lightPos, OpenGL picks the face of the major axis and reads
// (s,t) = ((sc/|ma| + 1)/2, (tc/|ma| + 1)/2) (GL 4.5, table 8.19). Each face's S P L^-1 must
// give the same (s,t), and r/q must equal the reference the shader computes.
TEST(PointLightFrustum, FacesFollowTheCubeMapTable) {
    ShadowBounds b;
    b.receivers.push_back(box({-20, -20, -20}, {20, 20, 20}));
    const glm::dvec3 p(1e6 + 0.25, 3.5, -2e6);
    b.receivers[0] = moved(b.receivers[0], p);
    engine::LightInstance li;
    li.world = glm::translate(glm::dmat4(1.0), p);
    const shadowmap::PointLightViews v =
        shadowmap::fitPointLight(li, makeLight(engine::Light::Type::Point), b);
    ASSERT_TRUE(v.valid) << v.invalidReason;

    std::mt19937_64 gen(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int counts[6] = {};
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 r(10 * u(gen), 10 * u(gen), 10 * u(gen));
        const glm::dvec3 a = glm::abs(r);
        int face;
        double sc, tc, ma;
        if (a.x >= a.y && a.x >= a.z) {
            face = r.x > 0 ? 0 : 1, ma = a.x, sc = r.x > 0 ? -r.z : r.z, tc = -r.y;
        } else if (a.y >= a.z) {
            face = r.y > 0 ? 2 : 3, ma = a.y, sc = r.x, tc = r.y > 0 ? r.z : -r.z;
        } else {
            face = r.z > 0 ? 4 : 5, ma = a.z, sc = r.z > 0 ? r.x : -r.x, tc = -r.y;
        }
        if (ma < v.nearPlane * 1.01) continue;
        ++counts[face];
        const glm::dvec4 c = v.faces[face].texgenPlanes() * glm::dvec4(p + r, 1.0);
        ASSERT_GT(c.w, 0.0);
        EXPECT_NEAR(c.x / c.w, 0.5 * (sc / ma + 1.0), 1e-9) << "face " << face;
        EXPECT_NEAR(c.y / c.w, 0.5 * (tc / ma + 1.0), 1e-9) << "face " << face;
        EXPECT_NEAR(c.z / c.w, shadowmap::cubeShadowReferenceDepth(r, v.nearPlane, v.farPlane),
                    1e-9);
        EXPECT_TRUE(v.faceSeesBox(face, box(p + r - 0.01, p + r + 0.01)));
    }
    for (int f = 0; f < 6; ++f) {
        EXPECT_GT(counts[f], 100) << "face " << f;
        EXPECT_EQ(glm::dvec3(v.faces[f].lightToWorld[3]), p);
        EXPECT_FALSE(v.faces[f].empty);
    }
}

TEST(PointLightFrustum, NearFarBracketReceiversWithinRange) {
    std::mt19937_64 gen(21);
    const ShadowBounds b = sceneBounds(gen);
    engine::LightInstance li;
    li.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 3.0, -0.5));
    const shadowmap::PointLightViews v =
        shadowmap::fitPointLight(li, makeLight(engine::Light::Type::Point, 0.5, 12.0), b);
    ASSERT_TRUE(v.valid) << v.invalidReason;
    EXPECT_LE(v.farPlane, 12.0 * 1.001 + 1e-12);
    for (const Aabb& r : b.receivers)
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 d = r.corner(i) - li.position();
            const double m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
            if (m > 12.0) continue;
            EXPECT_GE(m, v.nearPlane);
            EXPECT_LE(m, v.farPlane);
            const double ref = shadowmap::cubeShadowReferenceDepth(d, v.nearPlane, v.farPlane);
            EXPECT_GE(ref, 0.0);
            EXPECT_LE(ref, 1.0);
        }
}

// --- Helpers ---------------------------------------------------------------------------------

TEST(LightFrustumHelpers, RobustUpGivesOrthonormalFrames) {
    std::mt19937_64 gen(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<glm::dvec3> dirs = {{0, -1, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {1e-9, -1, 0}};
    for (int i = 0; i < 100; ++i) dirs.emplace_back(u(gen), u(gen), u(gen));
    for (const glm::dvec3& d : dirs) {
        const glm::dmat4 L = shadowmap::lightToWorldFromDirection({1, 2, 3}, d);
        const glm::dmat3 R(L);
        const glm::dmat3 I = glm::transpose(R) * R;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) EXPECT_NEAR(I[c][r], c == r ? 1.0 : 0.0, 1e-14);
        EXPECT_NEAR(glm::determinant(R), 1.0, 1e-14);
        EXPECT_NEAR(glm::dot(-R[2], glm::normalize(d)), 1.0, 1e-14);
    }
}

TEST(LightFrustumHelpers, BoundsFromSceneFollowFlags) {
    engine::Scene scene;
    engine::MeshInstance a, b;
    a.worldBounds = box({0, 0, 0}, {1, 1, 1});
    b.worldBounds = box({2, 2, 2}, {3, 3, 3});
    b.castShadows = false;
    scene.meshInstances = {a, b};
    const ShadowBounds s = ShadowBounds::fromScene(scene);
    ASSERT_EQ(s.casters.size(), 1u);
    ASSERT_EQ(s.receivers.size(), 2u);
    EXPECT_EQ(s.casters[0].min, a.worldBounds.min);
}

}  // namespace
