#pragma once
// --time and --animate for the tools: which of a scene's animations play, and the scene
// posed at a time. Time t poses every chosen animation at t (clamped to its own span, as
// engine::sampleAnimation does), so several animations of one file stay in step.
#include "engine/scene/Scene.h"

#include <string>
#include <vector>

namespace tools {

// The largest time a --time flag takes, in seconds: a bound on typos (11.6 days).
constexpr double kMaxAnimationSeconds = 1e6;

struct AnimationPlayback {
    std::vector<int> animations;  // indices into Scene::animations
    double startSeconds = 0.0;    // --time: the first frame's time
    double fps = 30.0;            // --fps: frame i is at startSeconds + i / fps
    bool animating = false;       // --animate given: frames advance; else every frame is at startSeconds

    double secondsAtFrame(int frame) const { return animating ? startSeconds + frame / fps : startSeconds; }
};

// The animations `selection` names: "all", or one animation's name. An unknown name throws
// std::invalid_argument naming the flag, the scene and the names it has.
std::vector<int> selectAnimations(const engine::Scene& scene, const std::string& sceneFile,
                                  const std::string& flag, const std::string& selection);

// Poses `playback`'s animations at `seconds` and recomposes the world transforms (and so
// the instances' bounds and revisions). Does nothing for no animations.
void poseScene(engine::Scene& scene, const AnimationPlayback& playback, double seconds);

} // namespace tools
