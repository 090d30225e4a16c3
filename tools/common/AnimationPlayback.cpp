#include "AnimationPlayback.h"

#include <stdexcept>

namespace tools {

std::vector<int> selectAnimations(const engine::Scene& scene, const std::string& sceneFile,
                                  const std::string& flag, const std::string& selection) {
    std::vector<int> chosen;
    if (selection == "all") {
        for (std::size_t i = 0; i < scene.animations.size(); ++i) chosen.push_back(static_cast<int>(i));
        return chosen;
    }
    const int found = engine::findAnimation(scene, selection);
    if (found >= 0) return {found};
    std::string names;
    for (const engine::Animation& animation : scene.animations)
        names += (names.empty() ? "" : ", ") + ("'" + animation.name + "'");
    throw std::invalid_argument(flag + ": " + sceneFile + " has no animation named '" + selection + "' (it has " +
                                (names.empty() ? std::string("none") : names) + "; or use all)");
}

void poseScene(engine::Scene& scene, const AnimationPlayback& playback, double seconds) {
    if (playback.animations.empty()) return;
    for (const int animation : playback.animations) engine::poseAnimation(scene, scene.animations[animation], seconds);
    scene.updateWorldTransforms();
}

} // namespace tools
