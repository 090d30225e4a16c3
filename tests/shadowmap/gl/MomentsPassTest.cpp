// The moments passes of filterable maps (plugin/MomentsRenderer.h, shaders/moments/) run on
// a depth map of known window depths, against the moments computed on the CPU in double
// from the same float depths:
//  - radius 0 (fromDepth alone, as MomentsPasses does): every texel holds its own moments,
//    VSM (u, u^2) and EVSM (e^(c+ x), its square, -e^(-c- x), its square; x = 2u - 1), for
//    orthographic and perspective depth, reversed and not, read through the 2D-array view of
//    a 2D map (layer 0) and of a two-layer array (layer 1, layer 0 holding other depths);
//  - radius r > 0: fromDepth along s into a rows texture, then blur along t, as
//    MomentsPasses does: the rows hold the CPU's box average along s and the target its box
//    average of those along t (weight 1 within floor(r), r - floor(r) for the next texel,
//    clamped at the edges, over the weights' sum).
//
// Tolerances from float precision, first order, per texel and per moment (MomentExpected):
// h = FLT_EPSILON / 2 is the relative error of one correctly rounded +, -, * (GLSL 4.50,
// 4.7.1); division is allowed 2.5 ULP and exp 3 + 2|y| ULP (one ULP <= FLT_EPSILON relative).
// The depth u carries a relative error e_u from its roundings (0 orthographic, h reversed
// orthographic; perspective: n z, the range f - n, z (f - n), the sum or difference with
// f or n, and the division, the denominator's roundings amplified by z (f - n) / D where the
// non-reversed denominator D = f - z (f - n) cancels toward n). VSM's u^2 adds 2 e_u + h.
// EVSM's x = 2u - 1 errs by 2u e_u + h|x|, y = c x by c times that + h|y|, and e^y errs
// relatively by that error of y plus exp's 3 + 2|y| ULP; its square doubles it plus h.
// The box passes add, per pass, h per rounding of the sum (all terms of a moment have one
// sign, so each partial sum is within the total) and 2.5 ULP for the division.
// No factor is added on top: the margin is what the spec allows beyond what llvmpipe does.
// Measured on Mesa llvmpipe 22.3 (printed by each test): exp's own error (ExpErrorWithin-
// GlslBound, where y is the same float on both sides) at most 22.7 ULP at y = -38.1, where
// 79 are allowed (its exp is exp2(y log2 e), so it errs ~0.6 |y| ULP), and 5.5 of 14.8 ULP
// at y = 5.9 for exponents [10, 3]; |GPU - CPU| at most 0.39 of its bound at radius 0, 0.39
// in the rows and 0.24 in the blurred moments, over all 18 depth and moment cases.
#include "../../gl/GlTestContext.h"

#include "plugin/MomentsRenderer.h"
#include "shadowmap/ShadowLimits.h"
#include "shadowmap/ShadowSettings.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Texture.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

constexpr int kSize = 64;
constexpr double kHalfUlp = FLT_EPSILON / 2.0;    // one correctly rounded +, -, *
constexpr double kDivision = 2.5 * FLT_EPSILON;   // GLSL's 2.5 ULP for x / y
constexpr glm::ivec2 kAlongS{1, 0}, kAlongT{0, 1};

// Window depths with a ramp, depths crowding toward 1 (where a perspective map's u is
// ill-conditioned), steps, scattered multiples of 1/64 with 0, and an exact 1: every value a
// float, so the CPU reads what the GPU reads. Row t = 0 is the texture's first row.
std::vector<float> knownDepths() {
    std::vector<float> depths(kSize * kSize);
    for (int t = 0; t < kSize; ++t)
        for (int s = 0; s < kSize; ++s) {
            float z;
            if (t < 16) z = (s + 0.5f) / kSize;                                      // ramp along s
            else if (t < 32) z = 1.0f - std::ldexp(1.0f, -(1 + (s + t) % 20));       // toward 1
            else if (t < 48) z = ((s / 8 + t / 8) % 2 ? 0.25f : 0.75f) + t / 1024.0f;  // steps
            else z = static_cast<float>((s * 37 + t * 11) % kSize) / kSize;          // scattered
            depths[t * kSize + s] = z;
        }
    depths[kSize * kSize - 1] = 1.0f;
    return depths;
}

struct Expected {
    glm::dvec4 value{0.0};
    glm::dvec4 bound{0.0};  // |GPU - value| allowed
};

// The depth u of window depth z (shaders/moments/moments.glsl: momentsDepth) and the
// relative error bound of the shader's float evaluation.
double momentsDepth(double z, const shadowmap::MomentsDepth& d, double& relativeError) {
    if (!d.perspective) {
        relativeError = d.reversed ? kHalfUlp : 0.0;
        return d.reversed ? 1.0 - z : z;
    }
    const double n = d.nearPlane, f = d.farPlane, p = z * (f - n);
    if (d.reversed) {
        const double denominator = p + n;
        // 1 - z, n (1 - z); the range and z * range (2h of p) and + n (h); the division.
        relativeError = 2 * kHalfUlp + (2 * kHalfUlp * p + kHalfUlp * denominator) / denominator + kDivision;
        return n * (1.0 - z) / denominator;
    }
    const double denominator = f - p;
    // n z; the range and z * range (2h of p) and f - that (h), over a denominator that
    // cancels toward n; the division.
    relativeError = kHalfUlp + (2 * kHalfUlp * p + kHalfUlp * denominator) / denominator + kDivision;
    return n * z / denominator;
}

// exp(y) of a y that errs by `yError`: its relative error bound, exp's own 3 + 2|y| ULP included.
double expRelativeError(double y, double yError) { return std::expm1(yError) + (3.0 + 2.0 * std::abs(y)) * FLT_EPSILON; }

Expected momentsOf(float z, const shadowmap::MomentsDepth& d) {
    double eu = 0.0;
    const double u = momentsDepth(z, d, eu);
    Expected e;
    if (!d.evsm) {
        e.value = {u, u * u, 0.0, 0.0};
        e.bound = {u * eu, u * u * (2 * eu + eu * eu + kHalfUlp), 0.0, 0.0};
        return e;
    }
    const double x = 2.0 * u - 1.0;
    const double xError = 2.0 * u * eu + kHalfUlp * std::abs(x);
    const double yp = d.exponents.x * x, yn = -d.exponents.y * x;
    const double ep = expRelativeError(yp, d.exponents.x * xError + kHalfUlp * std::abs(yp));
    const double en = expRelativeError(yn, d.exponents.y * xError + kHalfUlp * std::abs(yn));
    const double p = std::exp(yp), n = -std::exp(yn);
    e.value = {p, p * p, n, n * n};
    e.bound = {p * ep, p * p * (2 * ep + ep * ep + kHalfUlp), -n * en, n * n * (2 * en + en * en + kHalfUlp)};
    return e;
}

// The shaders' box weights along `step` (moments_box.glsl), clamped at the edges, applied
// to a field of dvec4 (values, or bounds: a bound's weighted mean bounds the mean's error).
std::vector<glm::dvec4> boxAverage(const std::vector<glm::dvec4>& field, glm::ivec2 step, double radius) {
    const int whole = static_cast<int>(std::floor(radius));
    const double fraction = radius - whole;
    std::vector<glm::dvec4> out(field.size());
    for (int t = 0; t < kSize; ++t)
        for (int s = 0; s < kSize; ++s) {
            glm::dvec4 sum(0.0);
            double weights = 0.0;
            for (int i = -whole - 1; i <= whole + 1; ++i) {
                const double w = std::abs(i) <= whole ? 1.0 : fraction;
                const int ss = std::clamp(s + i * step.x, 0, kSize - 1), tt = std::clamp(t + i * step.y, 0, kSize - 1);
                sum += w * field[tt * kSize + ss];
                weights += w;
            }
            out[t * kSize + s] = sum / weights;
        }
    return out;
}

// The relative rounding error of one box pass of `radius`: h for each rounding of the sum
// (2 floor(r) additions after the first, exact, one; three more for the fraction's pair), h
// for the weights' sum, and the division.
double boxPassRelativeError(double radius) {
    const int whole = static_cast<int>(std::floor(radius));
    const int roundings = 2 * whole + (radius > whole ? 3 : 0) + 1;
    return roundings * kHalfUlp + kDivision;
}

struct DepthCase {
    std::string name;
    shadowmap::MomentsDepth depth;
};

std::vector<DepthCase> depthCases() {
    std::vector<DepthCase> cases;
    struct Projection {
        const char* name;
        bool perspective;
        float nearPlane, farPlane;
    };
    const Projection projections[] = {
        {"orthographic", false, 0.0f, 0.0f},
        {"perspective 0.5-40", true, 0.5f, 40.0f},  // a typical fitted range: D cancels 80-fold
        {"perspective 10-12", true, 10.0f, 12.0f},  // a thin range
    };
    struct Moments {
        const char* name;
        bool evsm;
        glm::vec2 exponents;
    };
    const Moments kinds[] = {
        {"vsm", false, {0.0f, 0.0f}},
        {"evsm [40, 5]", true, {shadowmap::kMaxEvsmExponent, 5.0f}},  // the default, at the maximum
        {"evsm [10, 3]", true, {10.0f, 3.0f}},
    };
    for (const Projection& projection : projections)
        for (const bool reversed : {false, true})
            for (const Moments& kind : kinds) {
                shadowmap::MomentsDepth depth;
                depth.perspective = projection.perspective;
                depth.reversed = reversed;
                depth.nearPlane = projection.nearPlane;
                depth.farPlane = projection.farPlane;
                depth.evsm = kind.evsm;
                depth.exponents = kind.exponents;
                cases.push_back({std::string(kind.name) + ", " + projection.name + (reversed ? " reversed" : ""), depth});
            }
    return cases;
}

// Every texel of `target` against `expected`: the count beyond the bound, with the worst
// texel (by error over bound) described, and the worst error over bound.
struct Comparison {
    int outside = 0;
    double worstRatio = 0.0;
    std::string worst;
};

Comparison compare(const std::vector<float>& gpu, const std::vector<Expected>& expected, int channels) {
    Comparison c;
    for (int i = 0; i < kSize * kSize; ++i)
        for (int k = 0; k < channels; ++k) {
            const double error = std::abs(double(gpu[i * 4 + k]) - expected[i].value[k]);
            const double bound = expected[i].bound[k];
            const bool beyond = !(error <= bound);  // NaN counts
            c.outside += beyond;
            // NaN or an error where the bound is 0 ranks first.
            const double ratio = std::isnan(error) ? INFINITY : bound > 0.0 ? error / bound : error > 0.0 ? INFINITY : 0.0;
            if (ratio > c.worstRatio || (beyond && c.worst.empty())) {
                c.worstRatio = std::max(c.worstRatio, ratio);
                char text[256];
                std::snprintf(text, sizeof text, "texel (%d, %d) moment %d: GPU %.9g, CPU %.9g, bound %.3g", i % kSize,
                              i / kSize, k, gpu[i * 4 + k], expected[i].value[k], bound);
                c.worst = text;
            }
        }
    return c;
}

class MomentsPass : public engine::test::GlTest {
protected:
    static engine::gl::Texture depthMap(const std::vector<float>& depths) {
        engine::gl::Texture map = engine::gl::Texture::create2D(GL_DEPTH_COMPONENT32F, kSize, kSize);
        glTextureSubImage2D(map.id(), 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
        configureAsShadowMap(map);
        return map;
    }

    // Layer 1 holds `depths`, layer 0 other depths (1 - z): a pass reading the wrong layer fails.
    static engine::gl::Texture depthArray(const std::vector<float>& depths) {
        engine::gl::Texture map = engine::gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, kSize, kSize, 2);
        std::vector<float> other(depths.size());
        std::transform(depths.begin(), depths.end(), other.begin(), [](float z) { return 1.0f - z; });
        glTextureSubImage3D(map.id(), 0, 0, 0, 0, kSize, kSize, 1, GL_DEPTH_COMPONENT, GL_FLOAT, other.data());
        glTextureSubImage3D(map.id(), 0, 0, 0, 1, kSize, kSize, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
        configureAsShadowMap(map);
        return map;
    }

    // The state a shadow map has for its own lookups (comparison, bilinear PCF): the passes'
    // sampler must read plain texels regardless.
    static void configureAsShadowMap(engine::gl::Texture& map) {
        map.setParameter(GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        map.setParameter(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        map.setParameter(GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        map.setParameter(GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }

    // The map's 2D-array view, as LightShadow::ensureMoments makes it.
    static engine::gl::Texture layersView(const engine::gl::Texture& map, int layers) {
        GLuint view = 0;
        glGenTextures(1, &view);
        glTextureView(view, GL_TEXTURE_2D_ARRAY, map.id(), map.internalFormat(), 0, 1, 0, layers);
        engine::gl::Texture wrapped = engine::gl::Texture::wrap(view);
        configureAsShadowMap(wrapped);
        return wrapped;
    }

    // A colour target of the moments' format (LightShadow's momentsFormat), every texel
    // first set to a value no pass writes.
    static engine::gl::Texture momentsTarget(const shadowmap::MomentsDepth& depth) {
        engine::gl::Texture target = engine::gl::Texture::create2D(depth.evsm ? GL_RGBA32F : GL_RG32F, kSize, kSize);
        const float sentinel[4] = {-7.0f, -7.0f, -7.0f, -7.0f};
        glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, sentinel);
        return target;
    }

    // Runs `draw` into `target` with the moments passes' state (MomentsPasses.cpp:
    // no depth test or write, no culling, no blending).
    static void drawInto(const engine::gl::Texture& target, const std::function<void()>& draw) {
        engine::gl::Framebuffer framebuffer = engine::gl::Framebuffer::create();
        framebuffer.attach(GL_COLOR_ATTACHMENT0, target);
        framebuffer.requireComplete("moments pass test target");
        framebuffer.bind();
        glViewport(0, 0, kSize, kSize);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        draw();
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDepthMask(GL_TRUE);
    }

    // Level 0 as RGBA floats, row t = 0 first (as texelFetch and gl_FragCoord count).
    static std::vector<float> readBack(const engine::gl::Texture& texture) {
        std::vector<float> rgba(kSize * kSize * 4);
        glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                          rgba.data());
        return rgba;
    }

    static std::vector<Expected> expectedMoments(const std::vector<float>& depths, const shadowmap::MomentsDepth& d) {
        std::vector<Expected> expected;
        for (const float z : depths) expected.push_back(momentsOf(z, d));
        return expected;
    }
};

} // namespace

// Radius 0 gives the unblurred lookup: each texel's own moments.
TEST_F(MomentsPass, RadiusZeroWritesEachTexelsAnalyticMoments) {
    const shadowmap::MomentsRenderer renderer;
    const std::vector<float> depths = knownDepths();
    const engine::gl::Texture map = depthMap(depths);
    const engine::gl::Texture mapLayers = layersView(map, 1);
    const engine::gl::Texture array = depthArray(depths);
    const engine::gl::Texture arrayLayers = layersView(array, 2);
    struct Source {
        const char* name;
        unsigned view;
        int layer;
    };
    const Source sources[] = {{"2D map", mapLayers.id(), 0}, {"array layer 1", arrayLayers.id(), 1}};
    for (const DepthCase& c : depthCases()) {
        const std::vector<Expected> expected = expectedMoments(depths, c.depth);
        for (const Source& source : sources) {
            const engine::gl::Texture target = momentsTarget(c.depth);
            drawInto(target, [&] { renderer.fromDepth(source.view, source.layer, c.depth, 0.0f, kAlongS); });
            const std::vector<float> gpu = readBack(target);
            const Comparison result = compare(gpu, expected, c.depth.evsm ? 4 : 2);
            EXPECT_EQ(result.outside, 0) << c.name << ", " << source.name << ": " << result.outside
                                         << " moments beyond their bound; worst " << result.worst;
            std::printf("radius 0, %s, %s: worst |GPU - CPU| / bound %.3g\n", c.name.c_str(), source.name,
                        result.worstRatio);
        }
    }
}

// exp's own error on llvmpipe, against the GLSL bound the tolerances above use: on
// non-reversed orthographic depth u = z exactly, and x = 2z - 1 and y = c x are the same
// float on the CPU (2z is exact, so a fused 2z - 1 rounds as the unfused one), so the GPU's
// e^y differs from exp(double(y)) by exp's error and the store alone.
TEST_F(MomentsPass, ExpErrorWithinGlslBound) {
    const shadowmap::MomentsRenderer renderer;
    const std::vector<float> depths = knownDepths();
    const engine::gl::Texture map = depthMap(depths);
    const engine::gl::Texture mapLayers = layersView(map, 1);
    for (const glm::vec2 exponents : {glm::vec2(shadowmap::kMaxEvsmExponent, 5.0f), glm::vec2(10.0f, 3.0f)}) {
        shadowmap::MomentsDepth depth;
        depth.evsm = true;
        depth.exponents = exponents;
        const engine::gl::Texture target = momentsTarget(depth);
        drawInto(target, [&] { renderer.fromDepth(mapLayers.id(), 0, depth, 0.0f, kAlongS); });
        const std::vector<float> gpu = readBack(target);
        double worstUlp = 0.0, worstAllowed = 0.0, worstY = 0.0;
        int outside = 0;
        for (int i = 0; i < kSize * kSize; ++i) {
            const float x = 2.0f * depths[i] - 1.0f;
            const float ys[2] = {exponents.x * x, -exponents.y * x};
            const float warped[2] = {gpu[i * 4], -gpu[i * 4 + 2]};
            for (int k = 0; k < 2; ++k) {
                const double exact = std::exp(double(ys[k]));
                // One ULP of the exact result, as GLSL counts it.
                const double ulp = std::ldexp(1.0, std::ilogb(exact) - 23);
                const double ulps = std::abs(double(warped[k]) - exact) / ulp;
                const double allowed = 3.0 + 2.0 * std::abs(double(ys[k]));
                outside += !(ulps <= allowed);
                if (ulps > worstUlp) worstUlp = ulps, worstAllowed = allowed, worstY = ys[k];
            }
        }
        EXPECT_EQ(outside, 0) << "exponents [" << exponents.x << ", " << exponents.y << "]: " << outside
                              << " warps beyond 3 + 2|y| ULP; worst " << worstUlp << " ULP at y = " << worstY;
        std::printf("exponents [%g, %g]: exp's worst error %.3g ULP at y = %g (GLSL allows %g there)\n", exponents.x,
                    exponents.y, worstUlp, worstY, worstAllowed);
    }
}

// Radius r > 0: fromDepth along s into the rows, then blur along t into the moments, as
// MomentsPasses does; each against the CPU's box averages of the CPU moments.
TEST_F(MomentsPass, BlurredMomentsAreTheBoxAveragesOfTheMoments) {
    const shadowmap::MomentsRenderer renderer;
    const std::vector<float> depths = knownDepths();
    const engine::gl::Texture map = depthMap(depths);
    const engine::gl::Texture mapLayers = layersView(map, 1);
    // 0.5: the fraction alone; 1: whole texels alone; 2.5: both; the maximum, 16: 33 taps,
    // half the map clamped at the edges.
    const double radii[] = {0.5, 1.0, 2.5, shadowmap::kMaxFilterRadius};
    for (const DepthCase& c : depthCases()) {
        const std::vector<Expected> texels = expectedMoments(depths, c.depth);
        std::vector<glm::dvec4> values, magnitudes, bounds;
        for (const Expected& e : texels) {
            values.push_back(e.value);
            magnitudes.push_back(glm::abs(e.value));
            bounds.push_back(e.bound);
        }
        const int channels = c.depth.evsm ? 4 : 2;
        for (const double radius : radii) {
            const float r = static_cast<float>(radius);
            const double passError = boxPassRelativeError(radius);
            // Rows: the box along s. Its error: the texels' bounds averaged, and the pass's
            // roundings relative to the average magnitude (terms of one sign).
            const std::vector<glm::dvec4> rowValues = boxAverage(values, kAlongS, radius);
            const std::vector<glm::dvec4> rowMagnitudes = boxAverage(magnitudes, kAlongS, radius);
            const std::vector<glm::dvec4> rowTexelBounds = boxAverage(bounds, kAlongS, radius);
            std::vector<Expected> rowsExpected(values.size()), blurredExpected(values.size());
            std::vector<glm::dvec4> rowBounds(values.size());
            for (size_t i = 0; i < values.size(); ++i) {
                rowBounds[i] = rowTexelBounds[i] + passError * rowMagnitudes[i];
                rowsExpected[i] = {rowValues[i], rowBounds[i]};
            }
            // Moments: the rows' box along t; their bounds averaged, plus this pass's roundings.
            const std::vector<glm::dvec4> blurredValues = boxAverage(rowValues, kAlongT, radius);
            const std::vector<glm::dvec4> blurredMagnitudes = boxAverage(rowMagnitudes, kAlongT, radius);
            const std::vector<glm::dvec4> blurredRowBounds = boxAverage(rowBounds, kAlongT, radius);
            for (size_t i = 0; i < values.size(); ++i)
                blurredExpected[i] = {blurredValues[i], blurredRowBounds[i] + passError * blurredMagnitudes[i]};

            const engine::gl::Texture rows = momentsTarget(c.depth);
            const engine::gl::Texture moments = momentsTarget(c.depth);
            drawInto(rows, [&] { renderer.fromDepth(mapLayers.id(), 0, c.depth, r, kAlongS); });
            drawInto(moments, [&] { renderer.blur(rows.id(), r, kAlongT); });
            const Comparison rowsResult = compare(readBack(rows), rowsExpected, channels);
            const Comparison blurred = compare(readBack(moments), blurredExpected, channels);
            EXPECT_EQ(rowsResult.outside, 0) << c.name << ", radius " << radius << ", rows: " << rowsResult.outside
                                             << " moments beyond their bound; worst " << rowsResult.worst;
            EXPECT_EQ(blurred.outside, 0) << c.name << ", radius " << radius << ", blurred: " << blurred.outside
                                          << " moments beyond their bound; worst " << blurred.worst;
            std::printf("radius %g, %s: worst |GPU - CPU| / bound: rows %.3g, blurred %.3g\n", radius, c.name.c_str(),
                        rowsResult.worstRatio, blurred.worstRatio);
        }
    }
}
