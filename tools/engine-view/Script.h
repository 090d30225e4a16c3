#pragma once
// --script FILE: a text file of viewer commands, one per line, run one per frame (the
// frame after a command shows its effect). Blank lines and lines starting with '#' are
// skipped. The grammar:
//   key NAME               press a key (Controls::keyFromName: V, Tab, Esc, Space, Left, Right,
//                          [, ], ",", ".", "-", "=", 1...)
//   select LIGHT           select a light by name
//   set LIGHT KEY VALUE    set a key of the light's extras.shadow; VALUE is JSON, or a bare
//                          word taken as a string: `set sun resolution 1024`, `set sun
//                          variant woo`, `set sun polygon_offset [2, 6]`
//   view NAME              shaded | light | depth | projected | comparison | shadow | penumbra |
//                          truth | cascades
//   camera N|NAME|framing  a glTF camera by number (1 = first) or by name, or the framing one
//   orbit DX DY            a left-button drag of DX, DY pixels
//   pan DX DY              a right-button drag
//   zoom STEPS             wheel steps (> 0: closer)
//   frames N               render N frames (this command's included) before the next one
//   screenshot FILE.png    the window as shown after this command, as an RGB PNG
//   save [FILE]            write the scene with the lights' settings (default --save-settings)
//   overlay on|off         show or hide the text
//   resize W H             set the window's size
//   time T                 pose the scene at T seconds and pause (Playback.h)
//   play / pause           start or stop the animations (1/30 s per scripted frame)
//   quit                   close the viewer (exit 0)
// Load checks every line (unknown command, wrong argument count, bad number) and throws
// InputError "FILE:LINE: reason"; so does a command that cannot be done when it runs (no
// such light, camera, key or view). After the last command the viewer quits (exit 0), or
// stays interactive with --stay.
#include "Controls.h"
#include "OrbitCamera.h"
#include "ViewerState.h"

#include <filesystem>
#include <string>
#include <vector>

namespace engine_view {

class Script {
public:
    static Script load(const std::filesystem::path& path);
    static Script parse(const std::string& text, const std::string& fileName);

    bool finished() const { return next_ >= commands_.size() && wait_ == 0; }
    // Called once per frame: runs the next command unless a `frames N` still holds.
    void step(Controls& controls, ViewerState& state, OrbitCamera& camera, LoopRequests& requests,
              int viewportHeight);
    // "FILE:LINE" of the command run last, for errors found after it ran (a setting the
    // plugin refuses when it is applied).
    std::string where() const;
    std::size_t size() const { return commands_.size(); }
    // Before the window opens: every `screenshot PATH` can be written and every `save [PATH]`
    // can save `scene` there (PATH, else `defaultSave`, engine-view's --save-settings), so a
    // script never fails at its last line after running everything before it. Throws
    // InputError naming the line.
    void checkOutputs(const std::filesystem::path& scene, const std::string& defaultSave) const;

private:
    struct Command {
        int line = 0;
        std::string verb;
        std::vector<std::string> words;  // after the verb
        std::string rest;                // the line after the verb's second word (set's VALUE)
    };
    [[noreturn]] void fail(const Command& command, const std::string& reason) const;

    std::string fileName_;
    std::vector<Command> commands_;
    std::size_t next_ = 0;
    int wait_ = 0;      // frames still to render for the last `frames N`
    int lastLine_ = 0;
};

} // namespace engine_view
