#pragma once
// Program: a linked GLSL program built from one source string per stage.
// Uniforms are set with glProgramUniform* (no need to use() first) by name; locations are
// looked up once and cached. Setting a uniform the compiler optimised away is silently
// skipped, so shader variants (#define) can share the setting code.
#include "engine/gl/Handle.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace engine::gl {

namespace detail {
struct ProgramTraits {
    static constexpr GLenum labelNamespace = GL_PROGRAM;
    static void destroy(GLuint name) noexcept { glDeleteProgram(name); }
};
struct ProgramInfo {
    std::string name;
    // Filled lazily by the const uniformLocation(); -1 entries remember inactive uniforms.
    mutable std::unordered_map<std::string, GLint> uniformLocations;
};
} // namespace detail

class Program : public Handle<detail::ProgramTraits, detail::ProgramInfo> {
public:
    using Stage = std::pair<GLenum, std::string>; // {GL_VERTEX_SHADER, source}

    Program() = default;

    // Compiles every stage and links. Throws ShaderError naming the program and the stage
    // and quoting each source line the driver complains about (see ShaderLog.h).
    // The name also labels the program in GL debug output.
    static Program compile(const std::string& name, const std::vector<Stage>& stages);
    // How many programs compile() has linked in this process: a frame that links one pays
    // for it (llvmpipe also JIT-compiles at a program's first draw), so the renderer counts
    // them per frame (FrameResult::programsLinked).
    static std::uint64_t linkedCount();

    static Program wrap(GLuint name, std::string label = "wrapped",
                        Ownership ownership = Ownership::Adopt);

    const std::string& name() const { return info().name; }

    void use() const;

    // Cached glGetUniformLocation; -1 if the uniform is not active. For arrays, "lights"
    // and "lights[0]" both name the first element.
    GLint uniformLocation(const std::string& uniform) const;

    void set(const std::string& uniform, int value) const;
    void set(const std::string& uniform, unsigned value) const;
    void set(const std::string& uniform, float value) const;
    void set(const std::string& uniform, const glm::vec2& value) const;
    void set(const std::string& uniform, const glm::vec3& value) const;
    void set(const std::string& uniform, const glm::vec4& value) const;
    void set(const std::string& uniform, const glm::ivec2& value) const;
    void set(const std::string& uniform, const glm::ivec3& value) const;
    void set(const std::string& uniform, const glm::ivec4& value) const;
    void set(const std::string& uniform, const glm::mat3& value) const;
    void set(const std::string& uniform, const glm::mat4& value) const;
    // Arrays: uniform names the array; all elements are set from element 0.
    void set(const std::string& uniform, const std::vector<float>& values) const;
    void set(const std::string& uniform, const std::vector<glm::vec3>& values) const;
    void set(const std::string& uniform, const std::vector<glm::vec4>& values) const;
    void set(const std::string& uniform, const std::vector<glm::mat4>& values) const;

private:
    using Handle::Handle;
};

} // namespace engine::gl
