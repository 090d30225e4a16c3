// The uniform block as the GL compiles it from the shipped GLSL (hook code for a 2D map, a
// cube map and a cascaded map, and a soft-filtered 2D map, as the plugin generates it) against its CPU image
// plugin/ShadowBlock.h: the binding point, the size, every member's offset and array length.
// The GLSL takes the binding and MAX_CASCADES from the C++ constants, so the two cannot
// drift apart without this failing.
#include "../../gl/GlTestContext.h"

#include "plugin/HookGlsl.h"
#include "plugin/ShadowBlock.h"
#include "technique/Techniques.h"

#include "engine/gl/Program.h"
#include "engine/render/Frame.h"

#include <cstddef>
#include <string>

namespace {

using shadowmap::HookGlsl;
using shadowmap::ShadowBlock;

class ShadowBlockLayout : public engine::test::GlTest {
protected:
    static engine::gl::Program compileHook() {
        HookGlsl glsl;
        const std::string pcf = shadowmap::mapLookup(shadowmap::Filter::Pcf).glslName();
        const std::string pcss = shadowmap::mapLookup(shadowmap::Filter::Pcss).glslName();
        shadowmap::ShadowSettings wide;
        wide.filterRadius = 2.0;
        const std::string widePcf = shadowmap::mapLookupFor(wide).glslName();
        const HookGlsl::Code& code = glsl.codeFor({{0, 8, false, -1, 0, pcf},
                                                   {1, 9, true, -1, 0, pcf},
                                                   {2, 10, false, -1, 3, pcf},
                                                   {3, 11, false, -1, 0, pcss},
                                                   {4, 12, false, -1, 0, widePcf}});
        const std::string header = "#version 450 core\n#define MAX_LIGHTS " + std::to_string(engine::kMaxLights) + "\n";
        return engine::gl::Program::compile(
            "shadow block layout",
            {{GL_VERTEX_SHADER, header + code.vertex +
                                    "void main() {\n  lightTexgen(vec3(0.0, 0.0, -1.0));\n"
                                    "  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);\n}\n"},
             {GL_FRAGMENT_SHADER, header + code.fragment +
                                      "out vec4 outColor;\n"
                                      "void main() {\n  vec3 p = vec3(0.0, 0.0, -1.0), n = vec3(0.0, 0.0, 1.0);\n"
                                      "  outColor = vec4(lightVisibility(0, p, n), lightVisibility(1, p, n),\n"
                                      "                  lightVisibility(2, p, n), lightVisibility(3, p, n) + lightVisibility(4, p, n));\n}\n"}});
    }

    struct Member {
        GLint offset = -1, arraySize = -1;
    };
    static Member member(const engine::gl::Program& program, const std::string& name) {
        const GLuint index = glGetProgramResourceIndex(program.id(), GL_UNIFORM, name.c_str());
        EXPECT_NE(index, GL_INVALID_INDEX) << name << " is not in the compiled block";
        Member result;
        if (index == GL_INVALID_INDEX) return result;
        const GLenum properties[] = {GL_OFFSET, GL_ARRAY_SIZE};
        GLint values[2] = {-1, -1};
        glGetProgramResourceiv(program.id(), GL_UNIFORM, index, 2, properties, 2, nullptr, values);
        result.offset = values[0];
        result.arraySize = values[1];
        return result;
    }
};

TEST_F(ShadowBlockLayout, TheCompiledBlockIsTheCppStructAtTheCppBinding) {
    const engine::gl::Program program = compileHook();
    const GLuint block = glGetProgramResourceIndex(program.id(), GL_UNIFORM_BLOCK, "ShadowData");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum properties[] = {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE};
    GLint values[2] = {-1, -1};
    glGetProgramResourceiv(program.id(), GL_UNIFORM_BLOCK, block, 2, properties, 2, nullptr, values);
    EXPECT_EQ(values[0], static_cast<GLint>(shadowmap::kShadowBlockBinding));
    EXPECT_EQ(values[1], static_cast<GLint>(sizeof(ShadowBlock)));

    const struct {
        const char* name;
        std::size_t offset;
        int arraySize;
    } members[] = {
        {"ShadowData.eyePlanes[0]", offsetof(ShadowBlock, eyePlanes), engine::kMaxLights},
        {"ShadowData.params[0]", offsetof(ShadowBlock, params), engine::kMaxLights},
        {"ShadowData.lightInEye[0]", offsetof(ShadowBlock, lightInEye), engine::kMaxLights},
        {"ShadowData.pointFar[0]", offsetof(ShadowBlock, pointFar), engine::kMaxLights},
        {"ShadowData.eyeToWorld", offsetof(ShadowBlock, eyeToWorld), 1},
        {"ShadowData.cascadePlanes[0]", offsetof(ShadowBlock, cascadePlanes), engine::kMaxLights * shadowmap::kMaxCascades},
        {"ShadowData.cascadeFar[0]", offsetof(ShadowBlock, cascadeFar), engine::kMaxLights},
        {"ShadowData.cascadeBlend[0]", offsetof(ShadowBlock, cascadeBlend), engine::kMaxLights},
        {"ShadowData.softLayers[0]", offsetof(ShadowBlock, softLayers), engine::kMaxLights * shadowmap::kMaxCascades},
        {"ShadowData.lookupParams[0]", offsetof(ShadowBlock, lookupParams), engine::kMaxLights},
        {"ShadowData.texelWidths[0]", offsetof(ShadowBlock, texelWidths), engine::kMaxLights},
    };
    for (const auto& expected : members) {
        const Member compiled = member(program, expected.name);
        EXPECT_EQ(compiled.offset, static_cast<GLint>(expected.offset)) << expected.name;
        EXPECT_EQ(compiled.arraySize, expected.arraySize) << expected.name;
    }
}

} // namespace
