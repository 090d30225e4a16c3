#pragma once
// GlContext: an OpenGL context the engine renders with, headless (EGL, the default) or in a
// window (GLFW). The engine renders into its own framebuffers either way; a window only
// adds presenting (swapBuffers) and events.
//
// Each factory returns a context that is current on the calling thread.
#include "engine/util/Error.h"

#include <glm/vec2.hpp>

#include <memory>
#include <string>
#include <vector>

namespace engine {

// Creating a context failed (no EGL display, version refused, no window system, ...).
// An InputError: it depends on the machine, not on our code, and the tools report it on
// one line like any other bad input.
class ContextError : public InputError {
public:
    using InputError::InputError;
};

struct ContextOptions {
    int major = 4, minor = 5;   // llvmpipe (Mesa 22.3) offers 4.5 and refuses 4.6
    bool coreProfile = true;    // false: compatibility profile (fixed-function glTexGen, ...)
    bool debug = false;         // debug context + high-severity messages to stderr
    int width = 0, height = 0;  // window size, or the nominal size of a headless context;
                                // 0 = the factory's default
    std::string title;          // window title; empty = "engine"
    bool visible = true;        // window shown (GLFW); ignored headless
};

class GlContext {
public:
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
    virtual ~GlContext();

    virtual void makeCurrent() = 0;
    // Presents the back buffer; nothing to do headless.
    virtual void swapBuffers() {}
    virtual bool shouldClose() const { return false; }
    virtual void pollEvents() {}
    // The window's framebuffer in pixels; headless, the size asked for in ContextOptions.
    virtual glm::ivec2 framebufferSize() const { return {0, 0}; }

    // GL_RENDERER / GL_VERSION of the *current* context: make this one current first.
    std::string rendererString() const;
    std::string versionString() const;
};

// Headless: EGL with no surface at all (Mesa surfaceless platform, else the device
// platform, else the default display). Throws ContextError naming the step that failed.
//
// The environment variable ENGINE_EGL_DEVICE chooses the device, once per process (the
// display is opened on the first call):
//   unset or empty  the default above (Mesa llvmpipe on a machine without a GPU driver)
//   N               device N of listEglDevices(), through EGL_EXT_platform_device; a bad
//                   index or a device that cannot give a surfaceless context is a
//                   ContextError naming the devices there are
//   list            writes listEglDevices() to stderr, then opens the default
std::unique_ptr<GlContext> createEglContext(const ContextOptions& options = {});

// An EGL device (EGL_EXT_device_enumeration), as ENGINE_EGL_DEVICE names it.
struct EglDeviceInfo {
    int index = 0;
    std::string name;        // the DRM render node or device file, or "software"
    bool software = false;   // EGL_MESA_device_software: a CPU rasterizer (llvmpipe)
    std::string extensions;  // the device's EGL extensions
};
// Every EGL device in EGL's order; empty when EGL cannot enumerate devices.
std::vector<EglDeviceInfo> listEglDevices();
// One line per device: "EGL device N: NAME [software] (EXTENSIONS)".
std::string describeEglDevices(const std::vector<EglDeviceInfo>& devices);

// A GLFW window (default 1280×720) with a GL context; core profiles are forward compatible.
// Throws ContextError with GLFW's own description on failure (e.g. no display).
std::unique_ptr<GlContext> createGlfwContext(const ContextOptions& options);

} // namespace engine
