#pragma once
// Keys and mouse, from GLFW callbacks or from a script (`key V`, `orbit 30 0`): each turns
// into one edit of the ViewerState, a move of the OrbitCamera, or a request to the frame
// loop (save, quit, overlay, status message).
#include "OrbitCamera.h"
#include "Playback.h"
#include "ViewerState.h"

#include <string>

struct GLFWwindow;

namespace engine_view {

// What the frame loop does next; set by Controls and Script, cleared by the loop.
struct LoopRequests {
    bool redraw = true;      // something changed: render a frame
    bool quit = false;
    bool save = false;       // write the settings (to savePath, else --save-settings)
    std::string savePath;
    std::string screenshot;  // write the window of the next frame here
    bool overlay = true;
    int resizeWidth = 0, resizeHeight = 0;  // > 0: set the window's size
    std::string status;      // a message for the overlay (and stderr when an error)
    bool statusIsError = false;
    void say(std::string message, bool error = false) {
        status = std::move(message);
        statusIsError = error;
        redraw = true;
    }
};

class Controls {
public:
    Controls(ViewerState& state, OrbitCamera& camera, Playback& playback, LoopRequests& requests)
        : state_(state), camera_(camera), playback_(playback), requests_(requests) {}

    // Installs the key, mouse, scroll, size and refresh callbacks (the window's user
    // pointer is this object, which must outlive the window's events).
    void attach(GLFWwindow* window);

    // One press of a key (GLFW_KEY_*); unbound keys do nothing.
    void pressKey(int key);
    // A key by the name a script uses: a letter or digit, "Tab", "Esc", "Space", "Left",
    // "Right", "[", "]", ",", ".", "-", "=" (also "comma", "period", "minus", "equal");
    // GLFW_KEY_UNKNOWN (-1) for any other name.
    static int keyFromName(const std::string& name);

    void orbit(double dx, double dy) { camera_.orbit(dx, dy); requests_.redraw = true; }
    void pan(double dx, double dy, int viewportHeight) { camera_.pan(dx, dy, viewportHeight); requests_.redraw = true; }
    void zoom(double steps) { camera_.zoom(steps); requests_.redraw = true; }
    void seek(double seconds) { playback_.seek(seconds); requests_.redraw = true; }
    void setPlaying(bool playing) { playback_.setPlaying(playing); requests_.redraw = true; }

private:
    void say(const std::string& note);  // a key's note on the status line; "" says nothing
    void cursorMoved(GLFWwindow* window, double x, double y);

    ViewerState& state_;
    OrbitCamera& camera_;
    Playback& playback_;
    LoopRequests& requests_;
    int dragButton_ = -1;  // GLFW_MOUSE_BUTTON_* held, -1 none
    double lastX_ = 0.0, lastY_ = 0.0;
};

} // namespace engine_view
