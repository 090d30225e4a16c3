#include "Playback.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace engine_view {

Playback::Playback(engine::Scene& scene, tools::AnimationPlayback choice)
    : scene_(scene), choice_(std::move(choice)), seconds_(choice_.startSeconds) {
    bool first = true;
    for (const int index : choice_.animations) {
        const engine::Animation& animation = scene_.animations.at(index);
        start_ = first ? animation.startTime : std::min<double>(start_, animation.startTime);
        end_ = first ? animation.endTime : std::max<double>(end_, animation.endTime);
        first = false;
    }
}

void Playback::seek(double seconds) {
    playing_ = false;
    seconds_ = std::max(0.0, seconds);
    pose();
}

bool Playback::advance(double elapsed) {
    if (!playing_) return false;
    seconds_ += std::max(0.0, elapsed);
    // Wrap over the span [start, end] (a zero-length span holds its one pose).
    if (seconds_ > end_ && end_ > start_) seconds_ = start_ + std::fmod(seconds_ - start_, end_ - start_);
    pose();
    return true;
}

void Playback::pose() {
    if (!hasAnimations()) return;
    tools::poseScene(scene_, choice_, seconds_);
    posed_ = true;
}

std::string Playback::describe() const {
    if (!hasAnimations()) return "";
    char text[160];
    std::snprintf(text, sizeof text, "animation: %.2f s of %.2f-%.2f s, %s (Space: play/pause, Left/Right: step)",
                  seconds_, start_, end_, playing_ ? "playing" : posed_ ? "paused" : "at rest");
    return text;
}

} // namespace engine_view
