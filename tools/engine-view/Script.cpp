#include "Script.h"

#include "engine/render/CameraSetup.h"
#include "engine/util/Error.h"
#include "engine/util/InputFile.h"
#include "engine/util/OutputFile.h"

#include "SaveSettings.h"

#include <cerrno>
#include <cstdlib>
#include <map>
#include <sstream>

namespace engine_view {

namespace {

struct Arity {
    int min, max;
};

// Argument counts (words after the verb); `set` takes the rest of the line as its value.
const std::map<std::string, Arity> kCommands = {
    {"key", {1, 1}},     {"select", {1, 1}},     {"set", {3, 1 << 20}}, {"view", {1, 1}},
    {"camera", {1, 1}},  {"orbit", {2, 2}},      {"pan", {2, 2}},       {"zoom", {1, 1}},
    {"frames", {1, 1}},  {"screenshot", {1, 1}}, {"save", {0, 1}},      {"overlay", {1, 1}},
    {"resize", {2, 2}},  {"quit", {0, 0}},       {"time", {1, 1}},      {"play", {0, 0}},
    {"pause", {0, 0}}};

bool parseNumber(const std::string& text, double& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0' && errno == 0;
}

bool parseCount(const std::string& text, int maximum, int& value) {
    double number = 0.0;
    if (!parseNumber(text, number) || number != static_cast<int>(number) || number < 1 || number > maximum) return false;
    value = static_cast<int>(number);
    return true;
}

std::string knownCommands() {
    std::string list;
    for (const auto& [verb, arity] : kCommands) list += (list.empty() ? "" : ", ") + verb;
    return list;
}

} // namespace

Script Script::load(const std::filesystem::path& path) {
    return parse(engine::readWholeFile(path, "the script"), path.string());
}

void Script::fail(const Command& command, const std::string& reason) const {
    throw engine::InputError(fileName_ + ":" + std::to_string(command.line) + ": " + command.verb + ": " + reason);
}

void Script::checkOutputs(const std::filesystem::path& scene, const std::string& defaultSave) const {
    for (const Command& command : commands_) {
        try {
            if (command.verb == "screenshot") engine::checkOutputPath(command.words[0]);
            if (command.verb != "save") continue;
            const std::string path = command.words.empty() ? defaultSave : command.words[0];
            if (path.empty()) fail(command, "nowhere to save: give a path or start with --save-settings FILE.gltf");
            tools::checkSaveTarget(scene, path);
        } catch (const engine::InputError& error) {
            if (std::string(error.what()).rfind(fileName_ + ":", 0) == 0) throw;
            fail(command, error.what());
        }
    }
}

Script Script::parse(const std::string& text, const std::string& fileName) {
    Script script;
    script.fileName_ = fileName;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        Command command;
        command.line = number;
        if (!(words >> command.verb) || command.verb[0] == '#') continue;
        for (std::string word; words >> word;) command.words.push_back(word);
        const auto known = kCommands.find(command.verb);
        if (known == kCommands.end())
            throw engine::InputError(fileName + ":" + std::to_string(number) + ": unknown command \"" +
                                     command.verb + "\" (known: " + knownCommands() + ")");
        const int count = static_cast<int>(command.words.size());
        if (count < known->second.min || count > known->second.max)
            script.fail(command, "expected " +
                                     (known->second.min == known->second.max
                                          ? std::to_string(known->second.min)
                                          : std::to_string(known->second.min) + " or more") +
                                     " argument(s), got " + std::to_string(count));
        if (command.verb == "set") {
            // VALUE: everything after LIGHT and KEY, spaces included (JSON arrays).
            std::istringstream again(line);
            std::string skip;
            again >> skip >> skip >> skip;
            std::getline(again >> std::ws, command.rest);
            while (!command.rest.empty() && std::isspace(static_cast<unsigned char>(command.rest.back()))) command.rest.pop_back();
        }
        double number_ = 0.0;
        int count_ = 0;
        if ((command.verb == "orbit" || command.verb == "pan") &&
            !(parseNumber(command.words[0], number_) && parseNumber(command.words[1], number_)))
            script.fail(command, "DX and DY must be numbers");
        if (command.verb == "zoom" && !parseNumber(command.words[0], number_)) script.fail(command, "STEPS must be a number");
        if (command.verb == "time" && !(parseNumber(command.words[0], number_) && number_ >= 0.0 && number_ <= 1e6))
            script.fail(command, "T must be a number of seconds in [0, 1e6]");
        if (command.verb == "frames" && !parseCount(command.words[0], 100000, count_))
            script.fail(command, "N must be an integer in [1, 100000]");
        if (command.verb == "resize" &&
            !(parseCount(command.words[0], 16384, count_) && parseCount(command.words[1], 16384, count_)))
            script.fail(command, "W and H must be integers in [1, 16384]");
        if (command.verb == "overlay" && command.words[0] != "on" && command.words[0] != "off")
            script.fail(command, "expected on or off");
        if (command.verb == "view" && !parseView(command.words[0]))
            script.fail(command, "unknown view \"" + command.words[0] + "\" (" + viewNames() + ")");
        if (command.verb == "key" && Controls::keyFromName(command.words[0]) < 0)
            script.fail(command, "unknown key \"" + command.words[0] + "\"");
        script.commands_.push_back(std::move(command));
    }
    return script;
}

std::string Script::where() const { return fileName_ + ":" + std::to_string(lastLine_); }

void Script::step(Controls& controls, ViewerState& state, OrbitCamera& camera, LoopRequests& requests,
                  int viewportHeight) {
    requests.redraw = true;  // a script renders every frame it counts
    if (wait_ > 0) {
        --wait_;
        return;
    }
    if (next_ >= commands_.size()) return;
    const Command& command = commands_[next_++];
    lastLine_ = command.line;
    const std::vector<std::string>& w = command.words;
    const auto number = [](const std::string& text) { return std::strtod(text.c_str(), nullptr); };
    if (command.verb == "key") {
        controls.pressKey(Controls::keyFromName(w[0]));
    } else if (command.verb == "select") {
        if (!state.select(w[0])) fail(command, "no light \"" + w[0] + "\" in the scene");
    } else if (command.verb == "set") {
        const int index = state.find(w[0]);
        if (index < 0) fail(command, "no light \"" + w[0] + "\" in the scene");
        nlohmann::json value = nlohmann::json::parse(command.rest, nullptr, false);
        if (value.is_discarded()) value = command.rest;
        state.set(index, w[1], value);
    } else if (command.verb == "view") {
        state.setView(*parseView(w[0]));
    } else if (command.verb == "camera") {
        int index = 0;
        bool found = false;
        if (w[0] == engine::kFramingCameraName) found = camera.select(-1);
        else if (parseCount(w[0], 1 << 20, index)) found = camera.select(index - 1);
        else found = camera.selectByName(w[0]);
        if (!found) fail(command, "no camera \"" + w[0] + "\" in the scene");
    } else if (command.verb == "orbit") {
        controls.orbit(number(w[0]), number(w[1]));
    } else if (command.verb == "pan") {
        controls.pan(number(w[0]), number(w[1]), viewportHeight);
    } else if (command.verb == "zoom") {
        controls.zoom(number(w[0]));
    } else if (command.verb == "frames") {
        wait_ = static_cast<int>(number(w[0])) - 1;
    } else if (command.verb == "screenshot") {
        requests.screenshot = w[0];
    } else if (command.verb == "save") {
        requests.save = true;
        requests.savePath = w.empty() ? std::string() : w[0];
    } else if (command.verb == "overlay") {
        requests.overlay = w[0] == "on";
    } else if (command.verb == "resize") {
        requests.resizeWidth = static_cast<int>(number(w[0]));
        requests.resizeHeight = static_cast<int>(number(w[1]));
    } else if (command.verb == "time") {
        controls.seek(number(w[0]));
    } else if (command.verb == "play") {
        controls.setPlaying(true);
    } else if (command.verb == "pause") {
        controls.setPlaying(false);
    } else if (command.verb == "quit") {
        requests.quit = true;
    }
}

} // namespace engine_view
