// Programs: readable compile/link errors, uniforms, and drawing that is pixel-exact.
#include "GlTestContext.h"

#include "engine/gl/Buffer.h"
#include "engine/gl/Framebuffer.h"
#include "engine/gl/Program.h"
#include "engine/gl/Readback.h"
#include "engine/gl/Texture.h"
#include "engine/gl/VertexArray.h"

#include <array>

namespace engine::gl {
namespace {

using ProgramTest = test::GlTest;

// One triangle that covers the whole viewport, made from gl_VertexID alone.
const char* const kFullScreenVertex = R"(#version 450
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* const kUniformColorFragment = R"(#version 450
uniform vec4 uColor;
uniform float uUnused; // declared, never read: inactive
out vec4 fragColor;
void main() {
    fragColor = uColor;
}
)";

// k/255 components: exact in RGBA8, so drawn pixels must match bit for bit.
constexpr std::array<std::uint8_t, 4> kColor{51, 102, 153, 255};
const glm::vec4 kColorUniform = glm::vec4(kColor[0], kColor[1], kColor[2], kColor[3]) / 255.0f;

struct Target {
    static constexpr int kWidth = 64, kHeight = 32;
    Texture color = Texture::create2D(GL_RGBA8, kWidth, kHeight);
    Framebuffer framebuffer = Framebuffer::create();

    Target() {
        framebuffer.attach(GL_COLOR_ATTACHMENT0, color);
        framebuffer.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        framebuffer.requireComplete("program test target");
        const GLfloat black[] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, black);
        framebuffer.bind();
        glViewport(0, 0, kWidth, kHeight);
    }
    ~Target() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

    std::array<std::uint8_t, 4> pixel(const std::vector<std::uint8_t>& pixels, int x,
                                      int y) const {
        const std::size_t at = (static_cast<std::size_t>(y) * kWidth + x) * 4;
        return {pixels[at], pixels[at + 1], pixels[at + 2], pixels[at + 3]};
    }
    std::vector<std::uint8_t> read() const {
        return readPixelsRGBA8(framebuffer.id(), GL_COLOR_ATTACHMENT0, kWidth, kHeight);
    }
};

TEST_F(ProgramTest, CompileErrorQuotesTheOffendingLineAndItsNumber) {
    const std::string brokenFragment = "#version 450\n"
                                       "out vec4 fragColor;\n"
                                       "void main() {\n"
                                       "    float fine = 1.0;\n"
                                       "    fragColor = undefinedThing;\n"
                                       "}\n";
    try {
        Program::compile("broken", {{GL_VERTEX_SHADER, kFullScreenVertex},
                                    {GL_FRAGMENT_SHADER, brokenFragment}});
        FAIL() << "a broken shader compiled";
    } catch (const ShaderError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("Program 'broken': fragment shader failed to compile"),
                  std::string::npos) << message;
        EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
        EXPECT_NE(message.find("      5 |     fragColor = undefinedThing;"), std::string::npos)
            << message;
        EXPECT_EQ(message.find("float fine"), std::string::npos) << "quotes innocent lines";
    }
}

TEST_F(ProgramTest, LinkErrorNamesTheProgram) {
    try {
        Program::compile("no main", {{GL_VERTEX_SHADER, kFullScreenVertex},
                                     {GL_FRAGMENT_SHADER, "#version 450\nvoid helper() {}\n"}});
        FAIL() << "a program without a fragment main linked";
    } catch (const ShaderError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("Program 'no main' failed to link:", 0), 0u) << message;
        EXPECT_NE(message.find("main"), std::string::npos) << message;
    }
}

TEST_F(ProgramTest, UniformLocationsAreCachedAndInactiveOnesSkipped) {
    Program program = Program::compile("uniform colour", {{GL_VERTEX_SHADER, kFullScreenVertex},
                                                         {GL_FRAGMENT_SHADER,
                                                          kUniformColorFragment}});
    EXPECT_EQ(program.name(), "uniform colour");
    const GLint location = program.uniformLocation("uColor");
    EXPECT_GE(location, 0);
    EXPECT_EQ(program.uniformLocation("uColor"), location);
    EXPECT_EQ(program.uniformLocation("uUnused"), -1);
    EXPECT_EQ(program.uniformLocation("uMissing"), -1);
    // Setting inactive or missing uniforms is not an error (TearDown checks glGetError).
    program.set("uUnused", 1.0f);
    program.set("uMissing", glm::mat4(1.0f));
}

TEST_F(ProgramTest, MatrixAndArrayUniformsArriveIntact) {
    const char* fragment = R"(#version 450
uniform mat4 uMatrices[2];
uniform mat3 uNormal;
uniform vec3 uPoints[3];
uniform float uWeights[2];
uniform ivec2 uSize;
uniform uint uFlags;
out vec4 fragColor;
void main() {
    fragColor = uMatrices[0][0] + uMatrices[1][3] + vec4(uNormal[2], 0.0)
              + vec4(uPoints[2], uWeights[1]) + vec4(uSize, float(uFlags), 0.0);
}
)";
    Program program = Program::compile("uniform kinds", {{GL_VERTEX_SHADER, kFullScreenVertex},
                                                        {GL_FRAGMENT_SHADER, fragment}});
    const std::vector<glm::mat4> matrices{glm::mat4(2.0f), glm::mat4(3.0f)};
    const std::vector<glm::vec3> points{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
    program.set("uMatrices", matrices);
    program.set("uNormal", glm::mat3(5.0f));
    program.set("uPoints", points);
    program.set("uWeights", std::vector<float>{0.5f, 0.75f});
    program.set("uSize", glm::ivec2(640, 480));
    program.set("uFlags", 7u);

    auto floats = [&](const char* uniform, int count) {
        std::vector<GLfloat> values(static_cast<std::size_t>(count));
        glGetnUniformfv(program.id(), program.uniformLocation(uniform),
                        static_cast<GLsizei>(count * sizeof(GLfloat)), values.data());
        return values;
    };
    EXPECT_EQ(floats("uMatrices[1]", 16)[15], 3.0f);
    EXPECT_EQ(floats("uMatrices[1]", 16)[14], 0.0f);
    EXPECT_EQ(floats("uNormal", 9)[8], 5.0f);
    EXPECT_EQ(floats("uPoints[2]", 3), (std::vector<GLfloat>{7, 8, 9}));
    EXPECT_EQ(floats("uWeights[1]", 1)[0], 0.75f);
    GLint size[2] = {};
    glGetnUniformiv(program.id(), program.uniformLocation("uSize"), sizeof size, size);
    EXPECT_EQ(size[0], 640);
    EXPECT_EQ(size[1], 480);
    GLuint flags = 0;
    glGetnUniformuiv(program.id(), program.uniformLocation("uFlags"), sizeof flags, &flags);
    EXPECT_EQ(flags, 7u);
}

TEST_F(ProgramTest, FullScreenTriangleDrawsTheUniformColourExactly) {
    const Target target;
    Program program = Program::compile("uniform colour", {{GL_VERTEX_SHADER, kFullScreenVertex},
                                                         {GL_FRAGMENT_SHADER,
                                                          kUniformColorFragment}});
    program.set("uColor", kColorUniform);
    program.use();
    const VertexArray noAttributes = VertexArray::create(); // core profile needs one bound
    noAttributes.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);

    const auto pixels = target.read();
    for (int y = 0; y < Target::kHeight; ++y)
        for (int x = 0; x < Target::kWidth; ++x)
            ASSERT_EQ(target.pixel(pixels, x, y), kColor) << "at " << x << "," << y;
}

TEST_F(ProgramTest, IndexedQuadFromVertexArrayCoversExactlyTheLeftHalf) {
    const Target target;
    const char* vertex = R"(#version 450
layout(location = 0) in vec2 position;
void main() { gl_Position = vec4(position, 0.0, 1.0); }
)";
    Program program = Program::compile("left half", {{GL_VERTEX_SHADER, vertex},
                                                    {GL_FRAGMENT_SHADER,
                                                     kUniformColorFragment}});
    program.set("uColor", kColorUniform);

    // Interleaved with padding, so stride and offset both matter: {pad, x, y} per vertex.
    const std::array<float, 12> vertices{0, -1, -1, 0, 0, -1, 0, 0, 1, 0, -1, 1};
    const std::array<std::uint16_t, 6> indices{0, 1, 2, 0, 2, 3};
    const Buffer vertexBuffer = Buffer::create(sizeof vertices, vertices.data());
    const Buffer indexBuffer = Buffer::create(sizeof indices, indices.data());
    VertexArray vertexArray = VertexArray::create();
    vertexArray.attribute(0, vertexBuffer, 2, GL_FLOAT, 3 * sizeof(float), sizeof(float));
    vertexArray.elementBuffer(indexBuffer);

    program.use();
    vertexArray.bind();
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, nullptr);

    const auto pixels = target.read();
    const std::array<std::uint8_t, 4> clear{0, 0, 0, 0};
    for (int y = 0; y < Target::kHeight; ++y)
        for (int x = 0; x < Target::kWidth; ++x)
            ASSERT_EQ(target.pixel(pixels, x, y), x < Target::kWidth / 2 ? kColor : clear)
                << "at " << x << "," << y;
}

} // namespace
} // namespace engine::gl
