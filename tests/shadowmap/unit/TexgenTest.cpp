// Texgen algebra (Everitt et al., NVIDIA "Hardware Shadow Mapping", Equations 1-5 and Appendix A) checked in double, and the
// precision claim of Texgen.h: composed camera-relative in double, a scene 10^6 or 10^7
// units from the origin shadows as accurately as one at the origin.
#include "math/Texgen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace {

using shadowmap::TexCoord;
using shadowmap::Texgen;

struct Rng {
    std::mt19937_64 gen{0x5eed1234u};
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
    glm::dvec3 vec(double a, double b) { return {uniform(a, b), uniform(a, b), uniform(a, b)}; }
    glm::dmat4 rotation() {
        glm::dvec3 axis;
        do axis = vec(-1, 1);
        while (glm::length(axis) < 0.1);
        return glm::rotate(glm::dmat4(1.0), uniform(-3.1, 3.1), glm::normalize(axis));
    }
    glm::dmat4 rigid(double t) { return glm::translate(glm::dmat4(1.0), vec(-t, t)) * rotation(); }
    glm::dmat4 model() {  // rigid * non-uniform scale: M need not be orthonormal
        return rigid(10.0) * glm::scale(glm::dmat4(1.0), vec(0.5, 2.0));
    }
    glm::dmat4 perspective() {
        const double n = uniform(0.1, 2.0);
        return glm::perspectiveRH_NO(uniform(0.3, 2.0), uniform(0.5, 2.0), n,
                                     n * uniform(10, 1000));
    }
    glm::dmat4 ortho() {
        const double n = uniform(-5, 1);
        return glm::orthoRH_NO(uniform(-20, -1), uniform(1, 20), uniform(-20, -1), uniform(1, 20),
                               n, n + uniform(1, 100));
    }
};

glm::dmat4 absMat(const glm::dmat4& m) {
    glm::dmat4 a;
    for (int c = 0; c < 4; ++c) a[c] = glm::abs(m[c]);
    return a;
}

// Component-wise |a - b| <= rel * scale, where scale is the size of the terms summed.
void expectClose(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& scale, double rel,
                 const std::string& what) {
    for (int i = 0; i < 4; ++i)
        EXPECT_LE(std::abs(a[i] - b[i]), rel * scale[i] + 1e-300)
            << what << " component " << i << ": " << a[i] << " vs " << b[i];
}

TEST(Texgen, InitialPlanesAreOpenGLDefaults) {
    const Texgen tg;
    EXPECT_EQ(tg.eyePlane(TexCoord::S), glm::dvec4(1, 0, 0, 0));
    EXPECT_EQ(tg.eyePlane(TexCoord::T), glm::dvec4(0, 1, 0, 0));
    EXPECT_EQ(tg.eyePlane(TexCoord::R), glm::dvec4(0, 0, 0, 0));
    EXPECT_EQ(tg.eyePlane(TexCoord::Q), glm::dvec4(0, 0, 0, 0));
    EXPECT_EQ(tg.generate({3, 4, 5, 1}), glm::dvec4(3, 4, 0, 0));
}

TEST(Texgen, ScaleBiasRowsAndRange) {
    const glm::dmat4 s = shadowmap::scaleBias();
    EXPECT_EQ(glm::row(s, 0), glm::dvec4(0.5, 0, 0, 0.5));
    EXPECT_EQ(glm::row(s, 1), glm::dvec4(0, 0.5, 0, 0.5));
    EXPECT_EQ(glm::row(s, 2), glm::dvec4(0, 0, 0.5, 0.5));
    EXPECT_EQ(glm::row(s, 3), glm::dvec4(0, 0, 0, 1));
    EXPECT_EQ(s * glm::dvec4(-1, -1, -1, 1), glm::dvec4(0, 0, 0, 1));
    EXPECT_EQ(s * glm::dvec4(1, 1, 1, 1), glm::dvec4(1, 1, 1, 1));
}

// A hand-computed case that fails if rows and columns are swapped: the plane z = 5
// (world) specified while the camera at z = +10 looks down -Z (modelview translate(0,0,-10)).
TEST(Texgen, PlaneIsTransformedByInverseModelview) {
    Texgen tg;
    const glm::dmat4 view = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -10));
    tg.setEyePlane(TexCoord::S, {0, 0, 1, -5}, view);
    EXPECT_EQ(tg.eyePlane(TexCoord::S), glm::dvec4(0, 0, 1, 5));  // p * view^-1
    EXPECT_EQ(tg.eyePlane(TexCoord::T), glm::dvec4(0, 1, 0, 0));  // untouched
    // World (0,0,5) is eye (0,0,-5): on the plane. World (0,0,7) is 2 above it.
    EXPECT_EQ(tg.generate(view * glm::dvec4(0, 0, 5, 1)).x, 0.0);
    EXPECT_EQ(tg.generate(view * glm::dvec4(1, 2, 7, 1)).x, 2.0);
}

TEST(Texgen, SinglePlanesEqualRowsOfAllPlanes) {
    Rng rng;
    const glm::dmat4 planes = rng.perspective() * rng.rigid(5);
    const glm::dmat4 mv = rng.model();
    Texgen all, single;
    all.setEyePlanes(planes, mv);
    for (int i = 0; i < 4; ++i)
        single.setEyePlane(static_cast<TexCoord>(i), glm::row(planes, i), mv);
    for (int i = 0; i < 4; ++i) {
        const glm::dvec4 a = all.eyePlane(static_cast<TexCoord>(i));
        const glm::dvec4 b = single.eyePlane(static_cast<TexCoord>(i));
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[j], b[j], 1e-12 * (1 + std::abs(a[j])));
    }
}

// Equation 2 through Equation 1: planes Epo = S P L^-1 specified under modelview V^-1 give
// Texgen(V^-1 M x_o) = S P L^-1 M x_o, for perspective and orthographic lights alike; and the
// Appendix A alternatives (light-space planes S P under V^-1 L, identity planes under
// V^-1 L P^-1 S^-1) and Equation 5 (planes S P L^-1 V under identity) store the same Ee.
TEST(Texgen, ShadowTexgenEqualsLightClipCoordinates) {
    Rng rng;
    const glm::dmat4 S = shadowmap::scaleBias();
    double worst = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        const glm::dmat4 M = rng.model(), V = rng.rigid(20), L = rng.rigid(20);
        const glm::dmat4 P = (trial % 2) ? rng.ortho() : rng.perspective();
        const glm::dmat4 Epo = shadowmap::shadowTexgenPlanes(P, L);
        const glm::dmat4 viewInv = glm::inverse(V);

        Texgen worldPlanes, lightPlanes, identityPlanes, equation5;
        worldPlanes.setEyePlanes(Epo, viewInv);
        lightPlanes.setEyePlanes(S * P, viewInv * L);
        identityPlanes.setEyePlanes(glm::dmat4(1.0),
                                    viewInv * L * glm::inverse(P) * glm::inverse(S));
        equation5.setEyePlanes(S * P * glm::inverse(L) * V, glm::dmat4(1.0));
        const glm::dmat4 composed = shadowmap::eyePlanesForCamera(Epo, V);

        for (int k = 0; k < 8; ++k) {
            const glm::dvec4 xo(rng.vec(-1, 1), 1.0);
            const glm::dvec4 xw = M * xo;
            const glm::dvec4 xe = viewInv * M * xo;
            const glm::dvec4 expected = S * P * glm::inverse(L) * M * xo;
            // Size of the summed terms: a backward-error scale for the tolerance.
            const glm::dvec4 scale =
                glm::max(absMat(Epo) * glm::abs(xw), absMat(composed) * glm::abs(xe));
            const std::string what = "trial " + std::to_string(trial);
            expectClose(worldPlanes.generate(xe), expected, scale, 1e-12, what + " world planes");
            expectClose(lightPlanes.generate(xe), expected, scale, 1e-12, what + " light planes");
            expectClose(identityPlanes.generate(xe), expected, scale, 1e-12, what + " identity");
            expectClose(equation5.generate(xe), expected, scale, 1e-12, what + " equation 5");
            expectClose(composed * xe, expected, scale, 1e-12, what + " Epo*V");
            const glm::dvec4 d = worldPlanes.generate(xe) - expected;
            for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(d[i]) / scale[i]);
        }
    }
    RecordProperty("worst_relative_error", std::to_string(worst));
}

// --- Far from the origin -------------------------------------------------------------------

// A small scene: a spot light above objects, a camera looking at them. Translations are
// multiples of 2^-8 so that moving everything by T is exact in double: the true texture
// coordinates do not change, and the scene at the origin (double) is the reference.
struct FarScene {
    glm::dmat4 L, V, P;
    std::vector<glm::dmat4> models;
    std::vector<glm::dvec4> points;  // object space
};

glm::dmat4 poseLookingAt(const glm::dvec3& eye, const glm::dvec3& target) {
    glm::dmat4 m = glm::inverse(glm::lookAtRH(eye, target, glm::dvec3(0, 1, 0)));
    m[3] = glm::dvec4(eye, 1.0);  // exact position
    return m;
}

double quantize(double v) {
    return std::round(v * 256.0) / 256.0;
}

FarScene makeFarScene(bool orthographic) {
    Rng rng;
    FarScene s;
    s.L = poseLookingAt({3.0, 15.0, 8.0}, {0, 0, 0});
    s.V = poseLookingAt({20.0, 8.0, 25.0}, {0, 1, 0});
    s.P = orthographic ? glm::orthoRH_NO(-12.0, 12.0, -12.0, 12.0, 1.0, 40.0)
                       : glm::perspectiveRH_NO(1.2, 1.0, 2.0, 40.0);
    for (int i = 0; i < 16; ++i) {
        glm::dmat4 m = rng.rotation() * glm::scale(glm::dmat4(1.0), rng.vec(0.5, 2.0));
        const glm::dvec3 t = rng.vec(-8, 8);
        m[3] = glm::dvec4(quantize(t.x), quantize(t.y) * 0.25, quantize(t.z), 1.0);
        s.models.push_back(m);
    }
    for (int i = 0; i < 16; ++i) s.points.emplace_back(rng.vec(-1, 1), 1.0);
    return s;
}

glm::dmat4 movedBy(const glm::dmat4& m, const glm::dvec3& T) {
    glm::dmat4 out = m;
    out[3] = glm::dvec4(glm::dvec3(m[3]) + T, 1.0);  // exact for quantized translations
    return out;
}

glm::dvec3 projected(const glm::dvec4& strq) {
    return glm::dvec3(strq) / strq.w;
}

struct FarErrors {
    double doubleTexgen = 0, doubleComposed = 0, floatWorld = 0, floatRelative = 0;
};

FarErrors measureFarErrors(const FarScene& s, const glm::dvec3& T) {
    const glm::dmat4 S = shadowmap::scaleBias();
    const glm::dmat4 L = movedBy(s.L, T), V = movedBy(s.V, T);
    const glm::dmat4 viewInv = glm::inverse(V);

    const glm::dmat4 Epo = shadowmap::shadowTexgenPlanes(s.P, L);
    Texgen tg;
    tg.setEyePlanes(Epo, viewInv);                                // as OpenGL would, in double
    const glm::dmat4 Ee = shadowmap::eyePlanesForCamera(Epo, V);  // composed directly

    // What a naive GPU path does: one float32 world-space light matrix, float world positions.
    const glm::mat4 EpoFloat = glm::mat4(S) * glm::mat4(s.P) * glm::inverse(glm::mat4(L));
    // What the renderer should do: double-composed Ee and modelview, handed over as floats.
    const glm::mat4 EeFloat(Ee);

    FarErrors e;
    for (const glm::dmat4& model : s.models) {
        const glm::dmat4 M = movedBy(model, T);
        const glm::dmat4 modelView = viewInv * M;  // camera-relative, composed in double
        const glm::mat4 modelViewFloat(modelView);
        const glm::mat4 MFloat(M);
        for (const glm::dvec4& xo : s.points) {
            const glm::dvec3 ref = projected(S * s.P * glm::inverse(s.L) * model * xo);
            const glm::dvec4 xe = modelView * xo;
            auto err = [&](const glm::dvec3& v) {
                const glm::dvec3 d = glm::abs(v - ref);
                return std::max({d.x, d.y, d.z});
            };
            e.doubleTexgen = std::max(e.doubleTexgen, err(projected(tg.generate(xe))));
            e.doubleComposed = std::max(e.doubleComposed, err(projected(Ee * xe)));
            const glm::vec4 xwFloat = MFloat * glm::vec4(xo);
            e.floatWorld = std::max(e.floatWorld, err(projected(glm::dvec4(EpoFloat * xwFloat))));
            const glm::vec4 xeFloat = modelViewFloat * glm::vec4(xo);
            e.floatRelative =
                std::max(e.floatRelative, err(projected(glm::dvec4(EeFloat * xeFloat))));
        }
    }
    return e;
}

// Measured (Debian 12, x86-64, glm 0.9.9.8), max error over (s/q, t/q, r/q), 256 points:
//                         double Texgen  double Epo*V  float32 world  float32 of double Ee/eye
//   perspective, 10^6        1.7e-11       4.0e-11        9.4e-3           2.8e-7
//   perspective, 10^7        1.5e-10       7.1e-11        1.2e-1           2.8e-7
//   orthographic, 10^6       1.9e-11       3.6e-11        7.6e-3           2.4e-7
//   orthographic, 10^7       2.1e-10       9.1e-11        7.2e-2           2.4e-7
//   (at the origin float32 world-space is 1.7e-7 / 9.4e-8). The figures are printed and
//   recorded as test properties. Bounds, from precision and these measurements:
//   - double at T: the translation |T| is held to the spacing of doubles there, DBL_EPSILON*|T|,
//     and the texture coordinates' gain from a world position is below 1 (0.04 per unit for
//     the orthographic light, at most 0.37 for the perspective one), so a few such roundings
//     stay under DBL_EPSILON*|T|/2. Measured worst 0.134 * DBL_EPSILON*|T| (Epo*V at 10^6):
//     the bound has 3.7x margin, and scales with |T| instead of being one number for both.
//   - double at the origin: the same with |T| replaced by the scene's size (kSceneSize).
//   - float32 of the double-composed products: Ee and x_e rounded to float (u = FLT_EPSILON/2
//     each), four-term dot products of terms up to ~1.5 whose sum is <= 1, and the divide by q:
//     a few FLT_EPSILON. Measured 2.4 * FLT_EPSILON (2.8e-7); bound 8 * FLT_EPSILON (9.5e-7),
//     3.4x margin, independent of T.
constexpr double kSceneSize = 32.0;  // camera at ~33 and light at ~17 from the origin
class TexgenFarFromOrigin : public ::testing::TestWithParam<std::tuple<bool, double>> {};

TEST_P(TexgenFarFromOrigin, DoubleComposedStaysAccurate) {
    const auto [orthographic, distance] = GetParam();
    const FarScene scene = makeFarScene(orthographic);
    const glm::dvec3 T(distance, 0.5 * distance, -0.75 * distance);

    const FarErrors atOrigin = measureFarErrors(scene, glm::dvec3(0.0));
    const FarErrors far = measureFarErrors(scene, T);

    const double farBound = DBL_EPSILON * glm::length(T) / 2;
    EXPECT_LT(atOrigin.doubleTexgen, DBL_EPSILON * kSceneSize / 2);
    EXPECT_LT(far.doubleTexgen, farBound);
    EXPECT_LT(far.doubleComposed, farBound);
    // Floats of the double-composed, camera-relative products: what the GPU gets. Float
    // rounding of numbers of size ~10 to ~100 only, independent of T.
    EXPECT_LT(far.floatRelative, 8 * FLT_EPSILON);

    std::printf(
        "[ texgen  ] %s light at %.0e: double Texgen %.3g, double Epo*V %.3g, "
        "float32 world-space %.3g, float32 of double-composed Ee/eye coords %.3g "
        "(at origin: double Texgen %.3g = %.3g x DBL_EPSILON x scene size, float32 world-space %.3g); "
        "double errors at T = %.3g x DBL_EPSILON x |T|, float32 relative = %.3g x FLT_EPSILON\n",
        orthographic ? "ortho" : "persp", distance, far.doubleTexgen, far.doubleComposed,
        far.floatWorld, far.floatRelative, atOrigin.doubleTexgen,
        atOrigin.doubleTexgen / (DBL_EPSILON * kSceneSize), atOrigin.floatWorld,
        std::max(far.doubleTexgen, far.doubleComposed) / (DBL_EPSILON * glm::length(T)),
        far.floatRelative / FLT_EPSILON);
    RecordProperty("double_texgen_error", std::to_string(far.doubleTexgen));
    RecordProperty("double_composed_error", std::to_string(far.doubleComposed));
    RecordProperty("float_world_error", std::to_string(far.floatWorld));
    RecordProperty("float_relative_error", std::to_string(far.floatRelative));
}

INSTANTIATE_TEST_SUITE_P(Distances, TexgenFarFromOrigin,
                         ::testing::Combine(::testing::Bool(), ::testing::Values(1e6, 1e7)),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param) ? "Ortho" : "Perspective") +
                                    (std::get<1>(info.param) > 5e6 ? "At1e7" : "At1e6");
                         });

}  // namespace
