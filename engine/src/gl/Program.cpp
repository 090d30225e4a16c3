#include "engine/gl/Program.h"

#include "engine/gl/GlError.h"
#include "engine/gl/ShaderLog.h"

#include <glm/gtc/type_ptr.hpp>

#include <atomic>
#include <type_traits>

namespace engine::gl {

namespace {

const char* stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_TESS_CONTROL_SHADER: return "tessellation control";
    case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
    case GL_COMPUTE_SHADER: return "compute";
    default: return "unknown";
    }
}

template <typename GetIv, typename GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
    GLint length = 0;
    getIv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) getLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

// Shader objects only live until their program is linked; the same Handle owns them.
struct ShaderTraits {
    static constexpr GLenum labelNamespace = GL_SHADER;
    static void destroy(GLuint name) noexcept { glDeleteShader(name); }
};

class Shader : public Handle<ShaderTraits> {
public:
    explicit Shader(GLenum stage) : Handle(glCreateShader(stage), Ownership::Adopt, {}) {}
};

} // namespace

namespace {
std::atomic<std::uint64_t> linkedPrograms{0};
}

std::uint64_t Program::linkedCount() { return linkedPrograms.load(); }

Program Program::compile(const std::string& name, const std::vector<Stage>& stages) {
    ++linkedPrograms;
    Program program(glCreateProgram(), Ownership::Adopt, {name, {}});
    std::vector<Shader> shaders;
    shaders.reserve(stages.size());
    for (const auto& [stage, source] : stages) {
        const GLuint shader = shaders.emplace_back(stage).id();
        const char* text = source.c_str();
        const GLint length = static_cast<GLint>(source.size());
        glShaderSource(shader, 1, &text, &length);
        glCompileShader(shader);
        GLint compiled = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
        if (!compiled)
            throw ShaderError("Program '" + name + "': " + stageName(stage) +
                              " shader failed to compile:\n" +
                              annotateShaderLog(infoLog(shader, glGetShaderiv,
                                                        glGetShaderInfoLog),
                                                source));
        glAttachShader(program.id(), shader);
    }
    glLinkProgram(program.id());
    // Detached shaders are deleted with their owners; the program keeps its binary.
    for (const Shader& shader : shaders) glDetachShader(program.id(), shader.id());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (!linked)
        throw ShaderError("Program '" + name + "' failed to link:\n" +
                          infoLog(program.id(), glGetProgramiv, glGetProgramInfoLog));
    program.setLabel(name);
    return program;
}

Program Program::wrap(GLuint name, std::string label, Ownership ownership) {
    return Program(name, ownership, {std::move(label), {}});
}

void Program::use() const {
    glUseProgram(id());
}

GLint Program::uniformLocation(const std::string& uniform) const {
    auto& cache = info().uniformLocations;
    if (const auto found = cache.find(uniform); found != cache.end()) return found->second;
    const GLint location = glGetUniformLocation(id(), uniform.c_str());
    cache.emplace(uniform, location);
    return location;
}

namespace {

// Every setter: look the location up, skip inactive uniforms, hand the location to `call`.
template <typename Call>
void ifActive(const Program& program, const std::string& uniform, Call call) {
    if (const GLint location = program.uniformLocation(uniform); location >= 0) call(location);
}

template <typename T>
GLsizei countOf(const std::vector<T>& values) {
    return static_cast<GLsizei>(values.size());
}

// Element 0 as a pointer to its scalars; null for an empty array (GL then sets nothing).
template <typename T>
auto scalarsOf(const std::vector<T>& values) {
    if constexpr (std::is_arithmetic_v<T>) return values.data();
    else return values.empty() ? nullptr : glm::value_ptr(values.front());
}

} // namespace

void Program::set(const std::string& uniform, int value) const {
    ifActive(*this, uniform, [&](GLint at) { glProgramUniform1i(id(), at, value); });
}
void Program::set(const std::string& uniform, unsigned value) const {
    ifActive(*this, uniform, [&](GLint at) { glProgramUniform1ui(id(), at, value); });
}
void Program::set(const std::string& uniform, float value) const {
    ifActive(*this, uniform, [&](GLint at) { glProgramUniform1f(id(), at, value); });
}
void Program::set(const std::string& uniform, const glm::vec2& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform2fv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::vec3& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform3fv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::vec4& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform4fv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::ivec2& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform2iv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::ivec3& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform3iv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::ivec4& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform4iv(id(), at, 1, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::mat3& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniformMatrix3fv(id(), at, 1, GL_FALSE, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const glm::mat4& value) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniformMatrix4fv(id(), at, 1, GL_FALSE, glm::value_ptr(value));
    });
}
void Program::set(const std::string& uniform, const std::vector<float>& values) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform1fv(id(), at, countOf(values), scalarsOf(values));
    });
}
void Program::set(const std::string& uniform, const std::vector<glm::vec3>& values) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform3fv(id(), at, countOf(values), scalarsOf(values));
    });
}
void Program::set(const std::string& uniform, const std::vector<glm::vec4>& values) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniform4fv(id(), at, countOf(values), scalarsOf(values));
    });
}
void Program::set(const std::string& uniform, const std::vector<glm::mat4>& values) const {
    ifActive(*this, uniform, [&](GLint at) {
        glProgramUniformMatrix4fv(id(), at, countOf(values), GL_FALSE, scalarsOf(values));
    });
}

} // namespace engine::gl
