#pragma once
// Errors for bad input. Contract violations (our own bugs) are asserts; anything a user
// can get wrong (files, configs, settings, plugins) throws InputError with one sentence
// naming the file, the object and the reason. The CLIs catch it and print it on one line.
#include <stdexcept>
#include <string>

namespace engine {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    // Out of line (Error.cpp) on purpose: this key function makes libengine the one home
    // of InputError's vtable and type info. Were it inline, an InputError thrown by a
    // plugin would point into the plugin's code, and reading it after the plugin is
    // unloaded (the host unwinds first) would crash.
    ~InputError() override;
};

// An exception from plugin code that is not about the user's input (a bad pass declaration,
// a failed allocation, a broken invariant): the message names the plugin, and the type says
// the fault is the plugin's, so callers do not report it as a problem with the scene or config.
class PluginError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
    ~PluginError() override;  // out of line, for the reason given for InputError
};

// "file: object: reason" — the one format every bad-input message follows.
inline std::string describeError(const std::string& file, const std::string& object,
                                 const std::string& reason) {
    std::string message = file;
    if (!object.empty()) message += (message.empty() ? "" : ": ") + object;
    message += (message.empty() ? "" : ": ") + reason;
    return message;
}

[[noreturn]] inline void throwInputError(const std::string& file, const std::string& object,
                                         const std::string& reason) {
    throw InputError(describeError(file, object, reason));
}

} // namespace engine
