// Headless OpenGL through EGL with no surface: the context renders only into framebuffer
// objects, which is all the engine ever renders into. Works with Mesa llvmpipe on any Linux
// box, with no GPU, X server or Wayland compositor.
#include "engine/context/GlContext.h"

#include "engine/gl/DebugOutput.h"
#include "engine/gl/GlError.h"

#include <epoxy/egl.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377  // EGL_EXT_device_drm_render_node (newer headers)
#endif

namespace engine {

namespace {

std::string eglErrorName(EGLint error) {
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return gl::hexEnum(static_cast<GLenum>(error));
    }
}

std::string lastEglError() {
    return eglErrorName(eglGetError());
}

// Extension strings are space-separated names; match whole names only.
bool hasExtension(const char* extensions, const char* name) {
    if (!extensions) return false;
    const std::size_t length = std::strlen(name);
    for (const char* at = extensions; (at = std::strstr(at, name)) != nullptr; at += length) {
        const bool startsName = at == extensions || at[-1] == ' ';
        const bool endsName = at[length] == ' ' || at[length] == '\0';
        if (startsName && endsName) return true;
    }
    return false;
}

bool canEnumerateDevices() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    return hasExtension(client, "EGL_EXT_platform_base") &&
           hasExtension(client, "EGL_EXT_platform_device") &&
           hasExtension(client, "EGL_EXT_device_enumeration");
}

std::vector<EGLDeviceEXT> queryDevices() {
    if (!canEnumerateDevices()) return {};
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (!eglQueryDevicesEXT(count, devices.data(), &count)) return {};
    devices.resize(static_cast<std::size_t>(count));
    return devices;
}

// An initialised EGLDisplay. It lives as long as the process and is never terminated:
// - EGL displays are process-wide (the same native display gives the same handle), so
//   eglTerminate would also destroy contexts that other code in the process made on it;
// - Mesa unloads its driver on eglTerminate, so the next context would pay for loading
//   llvmpipe again, and memory the driver still referenced shows up as leaked under ASan.
struct EglDisplay {
    EGLDisplay handle = EGL_NO_DISPLAY;
    std::string platform; // which platform gave it, for messages
};

// Tries the platforms that need no window system, best first. Each failure is recorded so
// the final error says what was tried and why each one failed.
EglDisplay openDisplay() {
    // Client extensions (EGL_NO_DISPLAY) say which platforms this EGL library offers.
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const bool platformBase = hasExtension(client, "EGL_EXT_platform_base");

    struct Candidate {
        const char* platform;
        EGLDisplay display;
    };
    std::vector<Candidate> candidates;
    std::string reasons;
    auto note = [&](const std::string& reason) {
        reasons += (reasons.empty() ? "" : "; ") + reason;
    };

    if (platformBase && hasExtension(client, "EGL_MESA_platform_surfaceless"))
        candidates.push_back({"surfaceless", eglGetPlatformDisplayEXT(
                                                 EGL_PLATFORM_SURFACELESS_MESA,
                                                 EGL_DEFAULT_DISPLAY, nullptr)});
    else
        note("surfaceless platform not offered (EGL_MESA_platform_surfaceless)");

    if (canEnumerateDevices()) {
        const std::vector<EGLDeviceEXT> devices = queryDevices();
        if (!devices.empty())
            candidates.push_back(
                {"device", eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices.front(), nullptr)});
        else
            note("device platform: no EGL device");
    }

    candidates.push_back({"default", eglGetDisplay(EGL_DEFAULT_DISPLAY)});

    for (const Candidate& candidate : candidates) {
        if (candidate.display == EGL_NO_DISPLAY) {
            note(std::string(candidate.platform) + " display: " + lastEglError());
            continue;
        }
        EGLint major = 0, minor = 0;
        if (!eglInitialize(candidate.display, &major, &minor)) {
            note(std::string(candidate.platform) + " display: eglInitialize failed (" +
                 lastEglError() + ")");
            continue;
        }
        if (!hasExtension(eglQueryString(candidate.display, EGL_EXTENSIONS),
                          "EGL_KHR_surfaceless_context")) {
            // Left initialised, not terminated: see EglDisplay.
            note(std::string(candidate.platform) + " display: no EGL_KHR_surfaceless_context");
            continue;
        }
        return {candidate.display, candidate.platform};
    }
    throw ContextError("EGL: no surfaceless display: " + reasons);
}

// The display of device `choice` (ENGINE_EGL_DEVICE, a decimal index into listEglDevices()).
EglDisplay openChosenDevice(const std::string& choice) {
    const std::vector<EglDeviceInfo> infos = listEglDevices();
    const std::string prefix = "EGL: ENGINE_EGL_DEVICE=" + choice + ": ";
    if (infos.empty())
        throw ContextError(prefix + (canEnumerateDevices()
                                         ? "EGL lists no device"
                                         : "this EGL cannot enumerate devices (EGL_EXT_device_enumeration)"));
    char* end = nullptr;
    const long index = std::strtol(choice.c_str(), &end, 10);
    if (*end != '\0' || index < 0 || index >= static_cast<long>(infos.size())) {
        std::string known;
        for (const EglDeviceInfo& info : infos)
            known += (known.empty() ? "" : ", ") + std::to_string(info.index) + " = " + info.name;
        throw ContextError(prefix + "no such device (the devices: " + known + "; or `list`)");
    }
    const EGLDeviceEXT device = queryDevices().at(static_cast<std::size_t>(index));
    const std::string what = "ENGINE_EGL_DEVICE=" + choice + " (" + infos[index].name + ")";
    const EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY)
        throw ContextError("EGL: " + what + ": no display (" + lastEglError() + ")");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        throw ContextError("EGL: " + what + ": eglInitialize failed (" + lastEglError() + ")");
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        throw ContextError("EGL: " + what + ": no EGL_KHR_surfaceless_context");
    return {display, "device " + std::to_string(index) + " (" + infos[index].name + ")"};
}

// ENGINE_EGL_DEVICE (createEglContext in GlContext.h): the default display, or a chosen device.
EglDisplay openConfiguredDisplay() {
    const char* variable = std::getenv("ENGINE_EGL_DEVICE");
    const std::string choice = variable ? variable : "";
    if (choice.empty()) return openDisplay();
    if (choice == "list") {
        const std::vector<EglDeviceInfo> devices = listEglDevices();
        std::cerr << (devices.empty() ? std::string("EGL devices: none listed\n") : describeEglDevices(devices))
                  << std::flush;
        return openDisplay();
    }
    return openChosenDevice(choice);
}

// Opened on first use. If opening throws, the next call tries again (static initialisation
// is retried after an exception, and is thread-safe).
const EglDisplay& processDisplay() {
    static const EglDisplay display = openConfiguredDisplay();
    return display;
}

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context, glm::ivec2 size)
        : display_(display), context_(context), size_(size) {}

    ~EglContext() override {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw ContextError("EGL: eglMakeCurrent failed (" + lastEglError() + ")");
    }

    glm::ivec2 framebufferSize() const override { return size_; }

private:
    EGLDisplay display_;
    EGLContext context_;
    glm::ivec2 size_;
};

// With EGL_KHR_no_config_context a context needs no config (it never has a surface);
// otherwise any config that can do desktop GL will do.
EGLConfig chooseConfig(EGLDisplay display) {
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (hasExtension(extensions, "EGL_KHR_no_config_context") ||
        hasExtension(extensions, "EGL_MESA_configless_context"))
        return EGL_NO_CONFIG_KHR;
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &count) || count == 0)
        throw ContextError("EGL: no config for desktop OpenGL (" + lastEglError() + ")");
    return config;
}

std::string describe(const ContextOptions& options) {
    return "OpenGL " + std::to_string(options.major) + "." + std::to_string(options.minor) +
           (options.coreProfile ? " core" : " compatibility") +
           (options.debug ? " debug" : "") + " context";
}

} // namespace

std::vector<EglDeviceInfo> listEglDevices() {
    std::vector<EglDeviceInfo> infos;
    const std::vector<EGLDeviceEXT> devices = queryDevices();
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EglDeviceInfo info;
        info.index = static_cast<int>(i);
        const char* extensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        info.extensions = extensions ? extensions : "";
        info.software = hasExtension(extensions, "EGL_MESA_device_software");
        const char* node = nullptr;
        if (hasExtension(extensions, "EGL_EXT_device_drm_render_node"))
            node = eglQueryDeviceStringEXT(devices[i], EGL_DRM_RENDER_NODE_FILE_EXT);
        if (!node && hasExtension(extensions, "EGL_EXT_device_drm"))
            node = eglQueryDeviceStringEXT(devices[i], EGL_DRM_DEVICE_FILE_EXT);
        info.name = node ? node : info.software ? "software" : "unnamed";
        infos.push_back(std::move(info));
    }
    return infos;
}

std::string describeEglDevices(const std::vector<EglDeviceInfo>& devices) {
    std::string text;
    for (const EglDeviceInfo& device : devices)
        text += "EGL device " + std::to_string(device.index) + ": " + device.name +
                (device.software ? " [software]" : "") + " (" + device.extensions + ")\n";
    return text;
}

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options) {
    const EglDisplay& display = processDisplay();
    // The bound API is per thread: bind it on every call, not once with the display.
    if (!eglBindAPI(EGL_OPENGL_API))
        throw ContextError("EGL: desktop OpenGL not available on the " + display.platform +
                           " display (" + lastEglError() + ")");

    EGLint flags = 0;
    if (options.debug) flags |= EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR;
    // Same as the GLFW path, so a context behaves alike headless and windowed.
    if (options.coreProfile) flags |= EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR;
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION_KHR, options.major,
        EGL_CONTEXT_MINOR_VERSION_KHR, options.minor,
        EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR,
        options.coreProfile ? EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR
                            : EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT_KHR,
        EGL_CONTEXT_FLAGS_KHR, flags,
        EGL_NONE};
    const EGLContext context =
        eglCreateContext(display.handle, chooseConfig(display.handle), EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT)
        throw ContextError("EGL: cannot create an " + describe(options) + " on the " +
                           display.platform + " display (" + lastEglError() + ")");

    auto result = std::make_unique<EglContext>(display.handle, context,
                                               glm::ivec2(options.width, options.height));
    result->makeCurrent();
    if (options.debug) gl::installDebugOutput();
    return result;
}

} // namespace engine
