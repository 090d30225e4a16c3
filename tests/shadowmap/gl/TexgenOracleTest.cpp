// Our texgen emulation against the real thing: Mesa's compatibility profile still runs
// fixed-function EYE_LINEAR glTexGen. The same triangles are drawn twice into an RGBA32F
// target that receives (s,t,r,q) per pixel:
//   oracle    - fixed-function vertex stage: planes Epo = S*P_light*L^-1 given to glTexGen
//               while the modelview is V^-1, then the modelview V^-1*M for the draw;
//   emulation - the plugin's shipped vertex part (shaders/texgen.glsl, its shadowCoord) with
//               Ee from the CPU Texgen type in a slot other than 0, as the plugin binds it.
// Tolerance: Mesa transforms the eye planes and the vertices in float, so the
// coordinates here are moderate (|x| < 20) and the bound is relative: |diff| <= 32 FLT_EPSILON
// * (1 + |v|) = 3.8e-6 * (1 + |v|): both sides are float (Mesa inverts the modelview and
// transforms planes and vertices in float, the shipped shader gets Ee rounded once), a few
// dozen roundings. Measured 4.7e-7 to 1.1e-6 (9.3 FLT_EPSILON) over four random setups.
#include "../../gl/GlTestContext.h"

#include "ShippedShaders.h"

#include "math/Texgen.h"

#include "engine/gl/Framebuffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/Texture.h"
#include "engine/render/TextureReadback.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cfloat>
#include <random>

namespace {

constexpr int kSize = 64;

struct Transforms {
    glm::dmat4 model, eyeToWorld, lightToWorld, lightProjection, eyeProjection;
};

Transforms randomSetup(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto randomVec = [&](double scale) {
        return glm::dvec3(unit(random), unit(random), unit(random)) * scale;
    };
    Transforms setup;
    setup.model = glm::rotate(glm::translate(glm::dmat4(1.0), randomVec(3.0)), unit(random) * 3.0,
                              glm::normalize(randomVec(1.0) + glm::dvec3(0, 0, 1e-3)));
    setup.model = glm::scale(setup.model, glm::dvec3(1.5, 0.8, 1.2));
    setup.eyeToWorld = glm::inverse(glm::lookAt(glm::dvec3(0, 2, 12) + randomVec(1.0),
                                                glm::dvec3(0.0), glm::dvec3(0, 1, 0)));
    setup.lightToWorld = glm::inverse(glm::lookAt(glm::dvec3(6, 9, 4) + randomVec(2.0),
                                                  randomVec(1.0), glm::dvec3(0, 1, 0)));
    setup.lightProjection = glm::perspective(0.9, 1.0, 2.0, 30.0);
    setup.eyeProjection = glm::perspective(0.8, 1.0, 1.0, 50.0);
    return setup;
}

// A fan of triangles around the object's origin, big enough to cover much of the view.
std::vector<glm::dvec3> triangles() {
    std::vector<glm::dvec3> vertices;
    const int segments = 12;
    for (int i = 0; i < segments; ++i) {
        const double a0 = 2.0 * 3.14159265358979 * i / segments;
        const double a1 = 2.0 * 3.14159265358979 * (i + 1) / segments;
        vertices.push_back({0, 0, 0.5});
        vertices.push_back({4 * std::cos(a0), 4 * std::sin(a0), -0.5});
        vertices.push_back({4 * std::cos(a1), 4 * std::sin(a1), -0.5});
    }
    return vertices;
}

class TexgenOracle : public engine::test::GlTest {
protected:
    // Renders (s,t,r,q) per pixel into a float target; `draw` issues the draw calls.
    template <typename Draw>
    std::vector<float> capture(Draw draw) {
        engine::gl::Texture target = engine::gl::Texture::create2D(GL_RGBA32F, kSize, kSize);
        engine::gl::Texture depth = engine::gl::Texture::create2D(GL_DEPTH_COMPONENT24, kSize, kSize);
        engine::gl::Framebuffer framebuffer = engine::gl::Framebuffer::create();
        framebuffer.attach(GL_COLOR_ATTACHMENT0, target);
        framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
        framebuffer.requireComplete("texgen capture");
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glViewport(0, 0, kSize, kSize);
        const float clear[4] = {0, 0, 0, -1};  // q = -1 marks "not covered"
        glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
        const float farDepth = 1.0f;
        glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &farDepth);
        glEnable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        draw();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return engine::readTextureFloatTopDown(target, 4);
    }
};

} // namespace

TEST_F(TexgenOracle, EmulationMatchesFixedFunctionEyeLinearTexgen) {
    engine::ContextOptions options;
    options.coreProfile = false;
    const auto compatibility = engine::createEglContext(options);
    compatibility->makeCurrent();
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);

    const auto vertices = triangles();
    // Fixed-function vertex processing with a fragment-only program that writes the
    // generated coordinates: Mesa then runs real EYE_LINEAR texgen for the vertex stage.
    const engine::gl::Program writeTexcoord = engine::gl::Program::compile(
        "texgen oracle", {{GL_FRAGMENT_SHADER,
                           "#version 120\nvoid main() { gl_FragColor = gl_TexCoord[0]; }\n"}});
    // The shipped texgen.glsl under a main() that does what the lit pass's vertex stage does:
    // eye position from the modelview, then the hook's shadowCoord for one light's slot.
    constexpr int kSlot = 3;
    const engine::gl::Program emulation = engine::gl::Program::compile(
        "texgen emulation",
        {{GL_VERTEX_SHADER,
          shadowmap::test::hookPrelude() + shadowmap::shaders::texgen_glsl +
              "layout(location = 0) in vec3 inPosition;\n"
              "uniform mat4 uModelView, uProjection;\nout vec4 vTexcoord;\n"
              "void main() { vec4 e = uModelView * vec4(inPosition, 1.0);\n"
              "  vTexcoord = shadowCoord(" + std::to_string(kSlot) + ", e.xyz); gl_Position = uProjection * e; }\n"},
         {GL_FRAGMENT_SHADER, "#version 450 core\nin vec4 vTexcoord; out vec4 outColor;\n"
                              "void main() { outColor = vTexcoord; }\n"}});

    int compared = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const Transforms setup = randomSetup(seed);
        const glm::dmat4 view = glm::inverse(setup.eyeToWorld);  // V^-1
        const glm::dmat4 planes = shadowmap::shadowTexgenPlanes(setup.lightProjection, setup.lightToWorld);

        const auto oracle = capture([&] {
            writeTexcoord.use();
            glMatrixMode(GL_PROJECTION);
            glLoadMatrixd(glm::value_ptr(setup.eyeProjection));
            glMatrixMode(GL_MODELVIEW);
            glLoadMatrixd(glm::value_ptr(view));  // planes are specified under V^-1
            const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
            const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
            for (int i = 0; i < 4; ++i) {
                const glm::dvec4 plane = shadowmap::planeRow(planes, i);
                glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
                glTexGendv(coords[i], GL_EYE_PLANE, glm::value_ptr(plane));
                glEnable(enables[i]);
            }
            glLoadMatrixd(glm::value_ptr(view * setup.model));
            glBegin(GL_TRIANGLES);
            for (const glm::dvec3& v : vertices) glVertex3d(v.x, v.y, v.z);
            glEnd();
            for (GLenum e : enables) glDisable(e);
            glUseProgram(0);
        });

        shadowmap::Texgen texgen;
        texgen.setEyePlanes(planes, view);
        const auto emulated = capture([&] {
            std::vector<glm::vec3> floats(vertices.begin(), vertices.end());
            GLuint buffer = 0, vertexArray = 0;
            glGenVertexArrays(1, &vertexArray);
            glBindVertexArray(vertexArray);
            glGenBuffers(1, &buffer);
            glBindBuffer(GL_ARRAY_BUFFER, buffer);
            glBufferData(GL_ARRAY_BUFFER, floats.size() * sizeof(glm::vec3), floats.data(), GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
            emulation.use();
            emulation.set("uModelView", glm::mat4(view * setup.model));
            emulation.set("uProjection", glm::mat4(setup.eyeProjection));
            // The other slots hold a matrix that would give wrong coordinates if read.
            shadowmap::ShadowBlock block{};
            for (glm::mat4& planes : block.eyePlanes) planes = glm::mat4(2.0f);
            block.eyePlanes[kSlot] = glm::mat4(texgen.eyePlanes());
            const engine::gl::Buffer blockBuffer = shadowmap::test::bindShadowBlock(block);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(floats.size()));
            glUseProgram(0);
            glDeleteBuffers(1, &buffer);
            glDeleteVertexArrays(1, &vertexArray);
        });

        double worst = 0.0;
        int covered = 0;
        for (int pixel = 0; pixel < kSize * kSize; ++pixel) {
            // Pixels both draws covered (their rasterization can differ along edges).
            if (oracle[pixel * 4 + 3] == -1.0f || emulated[pixel * 4 + 3] == -1.0f) continue;
            ++covered;
            for (int c = 0; c < 4; ++c) {
                const double a = oracle[pixel * 4 + c], b = emulated[pixel * 4 + c];
                worst = std::max(worst, std::abs(a - b) / (1.0 + std::abs(a)));
            }
        }
        std::printf("seed %u: %d pixels, max relative difference %.3g\n", seed, covered, worst);
        EXPECT_GT(covered, 150) << "seed " << seed;
        EXPECT_LE(worst, 32 * FLT_EPSILON) << "seed " << seed;
        compared += covered;
    }
    EXPECT_GT(compared, 0);
}
