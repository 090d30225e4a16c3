#pragma once
// engine-view's animation clock. `--time T` poses the scene at T, `--animate NAME|all`
// chooses what plays and starts it; without either the scene shows at rest and Space starts
// every animation from T. Space plays and pauses, Left / Right step a tenth of a second back
// and forth (scrubbing pauses), and a script's `time T`, `play`, `pause` do the same. A
// playing clock advances by the wall-clock time between frames, or by 1/30 s per frame under
// a script, so a scripted run shows the same poses on every machine; past the end of the
// chosen animations it wraps to their start.
#include "AnimationPlayback.h"

#include "engine/scene/Scene.h"

#include <string>

namespace engine_view {

class Playback {
public:
    // `choice.animations` empty: the scene has none to play (the clock does nothing).
    Playback(engine::Scene& scene, tools::AnimationPlayback choice);

    bool hasAnimations() const { return !choice_.animations.empty(); }
    bool playing() const { return playing_; }
    double seconds() const { return seconds_; }

    void togglePlaying() { setPlaying(!playing_); }
    void setPlaying(bool playing) { playing_ = playing && hasAnimations(); }
    // Poses the scene at `seconds` (clamped at 0) and pauses.
    void seek(double seconds);
    // A playing clock moves on by `elapsed` seconds and poses the scene; true when it did.
    bool advance(double elapsed);

    // "animation: 1.25 s of 0-5.50 s, playing (Space: play/pause, Left/Right: step)", or
    // "" without animations.
    std::string describe() const;

private:
    void pose();

    engine::Scene& scene_;
    tools::AnimationPlayback choice_;
    double seconds_ = 0.0;
    double start_ = 0.0, end_ = 0.0;  // the chosen animations' span
    bool playing_ = false;
    bool posed_ = false;  // the scene shows a pose, not its rest
};

} // namespace engine_view
