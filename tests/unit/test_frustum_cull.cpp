// Box-versus-frustum culling from a view-projection matrix: exact answers for clear cases,
// never a false "outside" (checked against sampled points), and unchanged 10^6 from the origin.
#include "engine/scene/FrustumCull.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

namespace {

using engine::Aabb;
using engine::boxIntersectsFrustum;

Aabb box(glm::dvec3 a, glm::dvec3 b) {
    Aabb out;
    out.extend(a);
    out.extend(b);
    return out;
}

// Camera at T looking down -Z: view = translate(-T).
glm::dmat4 viewProjection(const glm::dmat4& projection, const glm::dvec3& T) {
    return projection * glm::translate(glm::dmat4(1.0), -T);
}

bool pointInside(const glm::dmat4& vp, const glm::dvec3& p) {
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    return c.w > 0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
}

TEST(FrustumCull, ClearCasesPerspectiveAndFarFromOrigin) {
    const glm::dmat4 P = glm::perspectiveRH_NO(glm::half_pi<double>(), 1.0, 1.0, 100.0);
    for (const glm::dvec3 T :
         {glm::dvec3(0.0), glm::dvec3(1e6, -2e6, 3e6), glm::dvec3(1e7, 0, 0)}) {
        const glm::dmat4 vp = viewProjection(P, T);
        auto at = [&](glm::dvec3 a, glm::dvec3 b) { return box(a + T, b + T); };
        EXPECT_TRUE(boxIntersectsFrustum(vp, at({-1, -1, -11}, {1, 1, -9}))) << "in front";
        EXPECT_FALSE(boxIntersectsFrustum(vp, at({-1, -1, 5}, {1, 1, 6}))) << "behind";
        EXPECT_FALSE(boxIntersectsFrustum(vp, at({-100, -1, -10}, {-90, 1, -9}))) << "left";
        EXPECT_FALSE(boxIntersectsFrustum(vp, at({-1, 20, -10}, {1, 30, -9}))) << "above";
        EXPECT_FALSE(boxIntersectsFrustum(vp, at({-1, -1, -200}, {1, 1, -150}))) << "beyond far";
        EXPECT_FALSE(boxIntersectsFrustum(vp, at({-0.1, -0.1, -0.9}, {0.1, 0.1, -0.5})))
            << "before near";
        EXPECT_TRUE(boxIntersectsFrustum(vp, at({-1, -1, -2}, {1, 1, 2}))) << "across near";
        EXPECT_TRUE(boxIntersectsFrustum(vp, at({-1e3, -1e3, -1e3}, {1e3, 1e3, 1e3})))
            << "encloses the frustum";
        EXPECT_TRUE(boxIntersectsFrustum(vp, at({9, -1, -10}, {12, 1, -9}))) << "across right";
    }
    EXPECT_FALSE(boxIntersectsFrustum(P, Aabb{})) << "empty box";
}

TEST(FrustumCull, Orthographic) {
    const glm::dmat4 vp = glm::orthoRH_NO(-5.0, 5.0, -2.0, 2.0, 0.0, 50.0);
    EXPECT_TRUE(boxIntersectsFrustum(vp, box({4, 1, -1}, {6, 3, 0})));
    EXPECT_FALSE(boxIntersectsFrustum(vp, box({5.5, 0, -10}, {6, 1, -9})));
    EXPECT_FALSE(boxIntersectsFrustum(vp, box({0, 0, 1}, {1, 1, 2})));
    EXPECT_FALSE(boxIntersectsFrustum(vp, box({0, 0, -60}, {1, 1, -51})));
}

// Conservative: whenever a sampled point of a box is inside, the box is reported inside.
TEST(FrustumCull, NeverCullsAVisibleBox) {
    std::mt19937_64 gen(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dmat4 vp =
        glm::perspectiveRH_NO(1.0, 1.5, 0.5, 60.0) *
        glm::lookAtRH(glm::dvec3(3, 4, 5), glm::dvec3(0, 0, -10), glm::dvec3(0, 1, 0));
    int inside = 0, culled = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 c(40 * u(gen), 40 * u(gen), 40 * u(gen) - 20);
        const glm::dvec3 h(3 * std::abs(u(gen)), 3 * std::abs(u(gen)), 3 * std::abs(u(gen)));
        const Aabb b = box(c - h, c + h);
        bool anyInside = false;
        for (int k = 0; k < 64 && !anyInside; ++k) {
            const glm::dvec3 t(0.5 * (u(gen) + 1), 0.5 * (u(gen) + 1), 0.5 * (u(gen) + 1));
            anyInside = pointInside(vp, b.min + t * (b.max - b.min));
        }
        for (int k = 0; k < 8 && !anyInside; ++k) anyInside = pointInside(vp, b.corner(k));
        const bool kept = boxIntersectsFrustum(vp, b);
        if (anyInside) {
            EXPECT_TRUE(kept) << "box " << i;
            ++inside;
        }
        if (!kept) ++culled;
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(culled, 1000);  // and it does cull
}

}  // namespace
