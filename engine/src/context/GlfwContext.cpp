// A window with an OpenGL context, through GLFW (GLX or Wayland underneath; epoxy resolves GL
// functions for whichever is current).
#include "engine/context/GlContext.h"

#include "engine/gl/DebugOutput.h"

#include <epoxy/gl.h>
// epoxy already declared GL; GLFW must not include a second GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>


namespace engine {

namespace {

constexpr int kDefaultWidth = 1280;
constexpr int kDefaultHeight = 720;

// GLFW reports errors through a callback; keep the last one for the exception message.
std::string& lastGlfwError() {
    static std::string message;
    return message;
}

void recordGlfwError(int code, const char* description) {
    lastGlfwError() = description ? description : "GLFW error " + std::to_string(code);
}

// GLFW is process-wide: initialised on first use and never terminated, like the EGL
// display. glfwTerminate would destroy windows other code made, and it closes the X
// connection, on which Mesa unloads its driver (reloading llvmpipe costs time, and memory
// the driver still referenced shows up as leaked under ASan).
void initialiseGlfw() {
    // A static's initialisation is thread-safe and retried if it throws, so a later attempt
    // (e.g. once DISPLAY is set) can still succeed. (Not std::call_once: with libstdc++ 12
    // a throwing call_once deadlocks the next caller, GCC PR 66146.)
    [[maybe_unused]] static const bool initialised = [] {
        glfwSetErrorCallback(recordGlfwError);
        if (!glfwInit()) throw ContextError("GLFW: cannot initialise: " + lastGlfwError());
        return true;
    }();
}

class GlfwContext final : public GlContext {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    ~GlfwContext() override {
        if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
        glfwDestroyWindow(window_);
    }

    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    void swapBuffers() override { glfwSwapBuffers(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_); }
    void pollEvents() override { glfwPollEvents(); }
    glm::ivec2 framebufferSize() const override {
        glm::ivec2 size;
        glfwGetFramebufferSize(window_, &size.x, &size.y);
        return size;
    }

private:
    GLFWwindow* window_;
};

} // namespace

std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options) {
    initialiseGlfw();
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, options.major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, options.minor);
    glfwWindowHint(GLFW_OPENGL_PROFILE,
                   options.coreProfile ? GLFW_OPENGL_CORE_PROFILE : GLFW_OPENGL_COMPAT_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, options.coreProfile ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);

    const int width = options.width > 0 ? options.width : kDefaultWidth;
    const int height = options.height > 0 ? options.height : kDefaultHeight;
    const std::string title = options.title.empty() ? "engine" : options.title;
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window)
        throw ContextError("GLFW: cannot open a " + std::to_string(width) + "x" +
                           std::to_string(height) + " window with OpenGL " +
                           std::to_string(options.major) + "." + std::to_string(options.minor) +
                           (options.coreProfile ? " core" : " compatibility") + ": " +
                           lastGlfwError());
    auto context = std::make_unique<GlfwContext>(window);
    context->makeCurrent();
    if (options.debug) gl::installDebugOutput();
    return context;
}

} // namespace engine
