#include "Controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cctype>
#include <exception>

namespace engine_view {

namespace {

constexpr double kScrubStep = 0.1;  // seconds per Left / Right press

Controls& controlsOf(GLFWwindow* window) { return *static_cast<Controls*>(glfwGetWindowUserPointer(window)); }

} // namespace

int Controls::keyFromName(const std::string& name) {
    if (name.size() == 1) {
        const unsigned char c = static_cast<unsigned char>(name[0]);
        if (std::isalpha(c)) return GLFW_KEY_A + (std::toupper(c) - 'A');
        if (std::isdigit(c)) return GLFW_KEY_0 + (c - '0');
        switch (c) {
        case '[': return GLFW_KEY_LEFT_BRACKET;
        case ']': return GLFW_KEY_RIGHT_BRACKET;
        case ',': return GLFW_KEY_COMMA;
        case '.': return GLFW_KEY_PERIOD;
        case '-': return GLFW_KEY_MINUS;
        case '=': return GLFW_KEY_EQUAL;
        default: return GLFW_KEY_UNKNOWN;
        }
    }
    if (name == "Tab") return GLFW_KEY_TAB;
    if (name == "Space") return GLFW_KEY_SPACE;
    if (name == "Left") return GLFW_KEY_LEFT;
    if (name == "Right") return GLFW_KEY_RIGHT;
    if (name == "Esc" || name == "Escape") return GLFW_KEY_ESCAPE;
    if (name == "comma") return GLFW_KEY_COMMA;
    if (name == "period") return GLFW_KEY_PERIOD;
    if (name == "minus") return GLFW_KEY_MINUS;
    if (name == "equal") return GLFW_KEY_EQUAL;
    return GLFW_KEY_UNKNOWN;
}

void Controls::pressKey(int key) {
    requests_.redraw = true;
    switch (key) {
    case GLFW_KEY_TAB: state_.selectNext(); break;
    case GLFW_KEY_V: state_.cycleVariant(); break;
    case GLFW_KEY_R: state_.cycleResolution(); break;
    case GLFW_KEY_F: state_.cycleDepthFormat(); break;
    case GLFW_KEY_P: state_.toggleFilter(); break;
    case GLFW_KEY_C: state_.cycleCascades(); break;
    case GLFW_KEY_T: state_.toggleStable(); break;
    case GLFW_KEY_LEFT_BRACKET: state_.addOffsetUnits(-1.0); break;
    case GLFW_KEY_RIGHT_BRACKET: state_.addOffsetUnits(1.0); break;
    case GLFW_KEY_COMMA: state_.addDimming(-0.05); break;
    case GLFW_KEY_PERIOD: state_.addDimming(0.05); break;
    case GLFW_KEY_MINUS: say(state_.shrinkLightSize()); break;
    case GLFW_KEY_EQUAL: say(state_.growLightSize()); break;
    case GLFW_KEY_D: state_.nextView(); break;
    case GLFW_KEY_M: state_.toggleTexelDensity(); break;
    case GLFW_KEY_O: requests_.overlay = !requests_.overlay; break;
    case GLFW_KEY_SPACE: playback_.togglePlaying(); break;
    case GLFW_KEY_LEFT: playback_.seek(playback_.seconds() - kScrubStep); break;
    case GLFW_KEY_RIGHT: playback_.seek(playback_.seconds() + kScrubStep); break;
    case GLFW_KEY_S: requests_.save = true; break;
    case GLFW_KEY_ESCAPE: requests_.quit = true; break;
    case GLFW_KEY_0: camera_.select(-1); break;
    default:
        if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9 && !camera_.select(key - GLFW_KEY_1))
            requests_.say("the scene has no camera " + std::to_string(key - GLFW_KEY_0), true);
        break;
    }
}

void Controls::say(const std::string& note) {
    if (!note.empty()) requests_.say(note);
}

void Controls::cursorMoved(GLFWwindow* window, double x, double y) {
    const double dx = x - lastX_, dy = y - lastY_;
    lastX_ = x, lastY_ = y;
    if (dragButton_ == GLFW_MOUSE_BUTTON_LEFT) orbit(dx, dy);
    else if (dragButton_ >= 0) {
        int width = 0, height = 0;
        glfwGetWindowSize(window, &width, &height);
        pan(dx, dy, height);
    }
}

void Controls::attach(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
        // No exception may cross GLFW's C frames: report it on the status line instead.
        try {
            controlsOf(w).pressKey(key);
        } catch (const std::exception& error) {
            controlsOf(w).requests_.say(std::string("key: ") + error.what(), true);
        }
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
        Controls& self = controlsOf(w);
        if (action == GLFW_PRESS && self.dragButton_ < 0) {
            self.dragButton_ = button;
            glfwGetCursorPos(w, &self.lastX_, &self.lastY_);
        } else if (action == GLFW_RELEASE && button == self.dragButton_) {
            self.dragButton_ = -1;
        }
    });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) { controlsOf(w).cursorMoved(w, x, y); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) { controlsOf(w).zoom(dy); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { controlsOf(w).requests_.redraw = true; });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { controlsOf(w).requests_.redraw = true; });
}

} // namespace engine_view
