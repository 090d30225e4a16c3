// --time, --fps and --animate values: numbers refused like integers are, animations chosen
// by name or "all", and frames placed in time.
#include "AnimationPlayback.h"
#include "OptionValues.h"

#include "ErrorOf.h"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace {

using tools::test::errorOf;

TEST(OptionValues, NumbersAreRead) {
    EXPECT_EQ(tools::parseNumber("--time", "0", 0, 1e6), 0.0);
    EXPECT_EQ(tools::parseNumber("--time", "1.25", 0, 1e6), 1.25);
    EXPECT_EQ(tools::parseNumber("--time", ".5", 0, 1e6), 0.5);
    EXPECT_EQ(tools::parseNumber("--fps", "2e1", 1e-3, 1e4), 20.0);
}

TEST(OptionValues, BadNumberNamesTheFlagTheTextAndTheRange) {
    for (const char* text : {"", "1s", " 1", "+1", "inf", "nan", "-inf", "0x10", "-1", "1e7"})
        EXPECT_EQ(errorOf([&] { tools::parseNumber("--time", text, 0, 1e6); }),
                  std::string("--time: \"") + text + "\" is not a number in [0, 1000000]");
}

engine::Scene sceneWithAnimations(std::initializer_list<const char*> names) {
    engine::Scene scene;
    for (const char* name : names) scene.animations.push_back({name, {}, {}, 0.0f, 0.0f});
    return scene;
}

TEST(AnimationPlayback, SelectsAllOrOneByName) {
    const engine::Scene scene = sceneWithAnimations({"walk", "wave"});
    EXPECT_EQ(tools::selectAnimations(scene, "s.gltf", "--animate", "all"), (std::vector<int>{0, 1}));
    EXPECT_EQ(tools::selectAnimations(scene, "s.gltf", "--animate", "wave"), (std::vector<int>{1}));
}

TEST(AnimationPlayback, UnknownNameListsTheSceneAnimations) {
    EXPECT_EQ(errorOf([] { tools::selectAnimations(sceneWithAnimations({"walk", "wave"}), "s.gltf", "--animate", "run"); }),
              "--animate: s.gltf has no animation named 'run' (it has 'walk', 'wave'; or use all)");
    EXPECT_EQ(errorOf([] { tools::selectAnimations(sceneWithAnimations({}), "s.gltf", "--animate", "run"); }),
              "--animate: s.gltf has no animation named 'run' (it has none; or use all)");
}

TEST(AnimationPlayback, FramesAdvanceOnlyWhenAnimating) {
    tools::AnimationPlayback playback;
    playback.startSeconds = 1.0;
    playback.fps = 4.0;
    EXPECT_EQ(playback.secondsAtFrame(3), 1.0);  // --time alone: a still frame
    playback.animating = true;
    EXPECT_EQ(playback.secondsAtFrame(0), 1.0);
    EXPECT_EQ(playback.secondsAtFrame(3), 1.75);
}

} // namespace
