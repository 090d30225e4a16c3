// The shipped cube-map reference depth (shaders/visibility.glsl: cubeMajorAxisDistance and
// cubeReferenceDepth, run in a fragment shader as the lit pass runs them) against its CPU
// twin cubeShadowReferenceDepth (math/LightFrustum.h, double), on directions toward all six
// faces, for finite and infinite far planes, with and without reversed Z.
//
// Tolerance from float precision: the GLSL forms f/(f-n) * (1 - n/m) and
// n/(f-n) * (f/m - 1) take five roundings of u = 2^-24 each (inputs n, f and the directions
// are floats, so the CPU sees the same numbers); the worst term is the rounding of n/m or
// f/m carried through the factor f/(f-n), so |GPU - CPU| <= u * (3 + f/(f-n)) when division
// is correctly rounded. GLSL allows division 2.5 ulp, so the bound doubles that:
// 4 * FLT_EPSILON * f/(f-n) (f/(f-n) := 1 for an infinite far plane).
#include "../../gl/GlTestContext.h"
#include "ShippedShaders.h"

#include "math/LightFrustum.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Framebuffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/Texture.h"
#include "engine/gl/VertexArray.h"
#include "engine/render/TextureReadback.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

namespace {

constexpr int kSamples = 384;  // 64 per cube face
constexpr int kSlot = 5;

struct CubeLight {
    float nearPlane, farPlane;  // farPlane 0: infinite, as the plugin uploads it
    bool reversed;
};

// Float directions whose major axis cycles through +x, -x, +y, -y, +z, -z, at distances
// spread geometrically from near to far (to 10^4 * near when far is infinite).
std::vector<glm::vec4> sampleDirections(const CubeLight& light) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> minor(-1.0f, 1.0f);
    const double farthest = light.farPlane > 0 ? light.farPlane : 1e4 * light.nearPlane;
    std::vector<glm::vec4> directions;
    for (int i = 0; i < kSamples; ++i) {
        const double t = (i + 0.5) / kSamples;
        const float major = static_cast<float>(light.nearPlane * std::pow(farthest / light.nearPlane, t));
        glm::vec3 v(minor(random) * major, minor(random) * major, minor(random) * major);
        v[(i / 2) % 3] = (i % 2 ? -major : major);
        directions.emplace_back(v, 0.0f);
    }
    return directions;
}

class CubeReferenceDepth : public engine::test::GlTest {
protected:
    // The shipped functions for every direction, one pixel each, as the GPU computes them.
    std::vector<float> shaderDepths(const CubeLight& light, const std::vector<glm::vec4>& directions) {
        const engine::gl::Program program = engine::gl::Program::compile(
            "cube reference depth",
            {{GL_VERTEX_SHADER, "#version 450 core\nvoid main() {\n"
                                "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n"},
             {GL_FRAGMENT_SHADER,
              shadowmap::test::hookPrelude() + shadowmap::shaders::map_shapes_glsl +
                  "layout(std430, binding = 0) readonly buffer Directions { vec4 toPoint[]; };\n"
                  "out vec4 outDepth;\n"
                  "void main() {\n"
                  "  vec3 v = toPoint[int(gl_FragCoord.x)].xyz;\n"
                  "  outDepth = vec4(cubeReferenceDepth(" + std::to_string(kSlot) + ", cubeMajorAxisDistance(v)));\n"
                  "}\n"}});
        // The other slots hold values that would give wrong depths if read.
        shadowmap::ShadowBlock block{};
        for (int slot = 0; slot < engine::kMaxLights; ++slot) {
            block.params[slot] = glm::vec4(1.0f - float(light.reversed), 0, 0, 0);
            block.lightInEye[slot] = glm::vec4(0, 0, 0, 1.0f);
            block.pointFar[slot] = glm::vec4(7.0f, 7.0f, 3.0f, 7.0f);
        }
        block.params[kSlot] = glm::vec4(light.reversed ? 1.0f : 0.0f, 0.0f, 0.4f, 1.0f);
        block.lightInEye[kSlot] = glm::vec4(1.0f, 2.0f, 3.0f, 1.0f);
        block.pointFar[kSlot].x = light.farPlane;
        block.pointFar[kSlot].z = light.nearPlane;
        const engine::gl::Buffer blockBuffer = shadowmap::test::bindShadowBlock(block);

        engine::gl::Buffer buffer = engine::gl::Buffer::create(directions.size() * sizeof(glm::vec4), directions.data());
        buffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
        engine::gl::Texture target = engine::gl::Texture::create2D(GL_RGBA32F, kSamples, 1);
        engine::gl::Framebuffer framebuffer = engine::gl::Framebuffer::create();
        framebuffer.attach(GL_COLOR_ATTACHMENT0, target);
        framebuffer.requireComplete("cube reference depth");
        const engine::gl::VertexArray empty = engine::gl::VertexArray::create();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glViewport(0, 0, kSamples, 1);
        glDisable(GL_DEPTH_TEST);
        program.use();
        glBindVertexArray(empty.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        const std::vector<float> rgba = engine::readTextureFloatTopDown(target, 4);
        std::vector<float> depths;
        for (int i = 0; i < kSamples; ++i) depths.push_back(rgba[i * 4]);
        return depths;
    }
};

} // namespace

TEST_F(CubeReferenceDepth, ShippedGlslMatchesTheCpuTwin) {
    const CubeLight lights[] = {
        {0.5f, 40.0f, false}, {0.5f, 40.0f, true},   // typical fitted range, f/(f-n) = 1.01
        {10.0f, 12.0f, false}, {10.0f, 12.0f, true},  // a thin range, f/(f-n) = 6
        {0.125f, 0.0f, false}, {0.125f, 0.0f, true},  // infinite far plane
    };
    for (const CubeLight& light : lights) {
        const bool infinite = light.farPlane <= 0;
        const double n = light.nearPlane;
        const double f = infinite ? std::numeric_limits<double>::infinity() : double(light.farPlane);
        const double condition = infinite ? 1.0 : f / (f - n);
        const double tolerance = 4.0 * FLT_EPSILON * condition;
        const std::vector<glm::vec4> directions = sampleDirections(light);
        const std::vector<float> gpu = shaderDepths(light, directions);
        double worst = 0.0;
        int worstSample = 0, outside = 0;
        for (int i = 0; i < kSamples; ++i) {
            const double cpu = shadowmap::cubeShadowReferenceDepth(glm::dvec3(glm::vec3(directions[i])), n, f,
                                                                   light.reversed);
            const double difference = std::abs(double(gpu[i]) - cpu);
            outside += difference > tolerance;
            if (difference > worst) worst = difference, worstSample = i;
        }
        const glm::vec4& d = directions[worstSample];
        EXPECT_EQ(outside, 0) << "near " << n << " far " << f << (light.reversed ? " reversed" : "") << ": "
                              << outside << " of " << kSamples << " directions beyond " << tolerance
                              << "; worst " << worst << " at (" << d.x << ", " << d.y << ", " << d.z << "): GPU "
                              << gpu[worstSample] << ", CPU "
                              << shadowmap::cubeShadowReferenceDepth(glm::dvec3(glm::vec3(d)), n, f, light.reversed);
        std::printf("near %g far %g%s: worst |GPU - CPU| %.3g = %.2f x FLT_EPSILON x f/(f-n) (bound 4)\n", n, f,
                    light.reversed ? " reversed" : "", worst, worst / (FLT_EPSILON * condition));
    }
}
