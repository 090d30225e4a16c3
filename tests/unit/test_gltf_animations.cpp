// glTF animations through the loader: what a valid file gives, and bad input refused with
// one message naming the file, the animation's channel or sampler, and the reason.
#include "engine/gltf/GltfLoader.h"
#include "engine/scene/Animation.h"
#include "engine/util/Error.h"

#include "gltf_test_support.h"
#include "../support/AssimpTestModels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <ostream>

namespace {

using namespace gltf_test;

// The quad scene whose node 0 carries the 'SlideTurnGrow' animation (gltf_writer.h).
GltfBuilder animatedQuad() {
    GltfBuilder b = quadScene();
    addSlideTurnGrowAnimation(b, 0);
    return b;
}

json& animation(GltfBuilder& b) { return b.doc["animations"][0]; }

TEST(GltfAnimations, LoadsEveryInterpolationAndPosesTheNode) {
    TempDir dir;
    std::vector<std::string> warnings;
    engine::Scene scene = engine::loadGltf(animatedQuad().writeGltf(dir.path(), "animated"), &warnings);
    for (const std::string& warning : warnings) EXPECT_EQ(warning.find("animation"), std::string::npos) << warning;
    ASSERT_EQ(scene.animations.size(), 1u);
    const engine::Animation& slide = scene.animations[0];
    EXPECT_EQ(slide.name, "SlideTurnGrow");
    EXPECT_EQ(slide.startTime, 0.0f);
    EXPECT_EQ(slide.endTime, 1.0f);
    ASSERT_EQ(slide.channels.size(), 3u);
    EXPECT_EQ(slide.samplers[1].interpolation, engine::Interpolation::Step);
    EXPECT_EQ(slide.samplers[2].interpolation, engine::Interpolation::CubicSpline);

    engine::poseAnimation(scene, slide, 0.5);
    scene.updateWorldTransforms();
    const engine::Node& node = scene.nodes[0];
    EXPECT_DOUBLE_EQ(node.translation.x, 1.0);  // halfway from 0 to 2
    EXPECT_EQ(node.rotation, glm::dquat(1, 0, 0, 0));  // STEP still holds the first key
    // Flat tangents at s = 0.5: h00 + 3 h01 = 0.5 + 1.5 = 2.
    EXPECT_NEAR(node.scale.x, 2.0, 1e-6);  // float keys and result: a few ulps of 2
    // The quad [0,1]^2 scaled by 2 and moved by 1 along x.
    EXPECT_NEAR(scene.meshInstances[0].worldBounds.max.x, 3.0, 1e-6);
}

TEST(GltfAnimations, NormalizedIntegerRotationKeysAreReadAsUnitQuaternions) {
    TempDir dir;
    engine::Scene scene = engine::loadGltf(animatedQuad().writeGltf(dir.path(), "animated"));
    // Key 1 is (0, 0, 23170, 23170) / 32767 = 0.70710...(1 - 7e-6): normalized at load to
    // exactly a half turn's quaternion; 1e-7 is about one float ulp at 0.7.
    const std::vector<float> q =
        engine::sampleAnimation(scene.animations[0].samplers[1], engine::AnimationPath::Rotation, 1.0);
    EXPECT_NEAR(q[2], std::sqrt(0.5f), 1e-7f);
    EXPECT_NEAR(q[3], std::sqrt(0.5f), 1e-7f);
}

TEST(GltfAnimations, UnusedSamplerIsWarnedAboutAndKeptEmpty) {
    TempDir dir;
    GltfBuilder b = animatedQuad();
    animation(b)["channels"].erase(1);
    std::vector<std::string> warnings;
    const engine::Scene scene = engine::loadGltf(b.writeGltf(dir.path(), "unused"), &warnings);
    EXPECT_EQ(scene.animations[0].channels.size(), 2u);
    EXPECT_TRUE(scene.animations[0].samplers[1].times.empty());
    EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
        return w.find("animations[0] 'SlideTurnGrow'.samplers[1]: no channel uses it") != std::string::npos;
    }));
}

// Files no one here wrote (Debian's assimp-testmodels); the facts checked are in their JSON.
TEST(GltfAnimations, SimpleSkinTurnsItsJointOverFivePointFiveSeconds) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    engine::Scene scene = engine::loadGltf(engine::test::kAssimpGltf2Models / "simple_skin/simple_skin.gltf");
    ASSERT_EQ(scene.animations.size(), 1u);
    const engine::Animation& animation = scene.animations[0];
    ASSERT_EQ(animation.channels.size(), 1u);
    EXPECT_EQ(animation.channels[0].node, 2);
    EXPECT_EQ(animation.channels[0].path, engine::AnimationPath::Rotation);
    EXPECT_EQ(animation.samplers[0].times.size(), 12u);
    EXPECT_EQ(animation.startTime, 0.0f);
    EXPECT_EQ(animation.endTime, 5.5f);
    // The file's keys turn the joint about Z up to 90 degrees each way (output min/max z
    // -0.707 / 0.707). At a key's time the pose is that key.
    const engine::AnimationSampler& turn = animation.samplers[0];
    std::size_t turned = 0;
    while (turned < turn.times.size() && std::abs(turn.values[4 * turned + 2]) < 0.5f) ++turned;
    ASSERT_LT(turned, turn.times.size()) << "no key turns more than 60 degrees";
    const glm::dmat4 rest = scene.nodes[2].local;
    engine::poseAnimation(scene, animation, turn.times[turned]);
    EXPECT_NEAR(scene.nodes[2].rotation.z, turn.values[4 * turned + 2], 1e-7);  // float key, double pose
    EXPECT_NEAR(glm::length(scene.nodes[2].rotation), 1.0, 1e-7);
    EXPECT_NE(scene.nodes[2].local, rest);
}

TEST(GltfAnimations, AnimatedMorphCubeAnimatesBothTargetWeights) {
    ASSERT_TRUE(engine::test::assimpTestModelsInstalled());
    std::vector<std::string> warnings;
    engine::Scene scene = engine::loadGltf(
        engine::test::kAssimpGltf2Models / "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(scene.animations.size(), 1u);
    const engine::Animation& square = scene.animations[0];
    EXPECT_EQ(square.name, "Square");
    ASSERT_EQ(square.channels.size(), 1u);
    EXPECT_EQ(square.channels[0].path, engine::AnimationPath::Weights);
    EXPECT_EQ(square.samplers[0].components, 2u);  // 254 outputs for 127 keys
    ASSERT_EQ(scene.meshInstances.size(), 1u);
    const engine::Aabb rest = scene.meshInstances[0].worldBounds;
    engine::poseAnimation(scene, square, 2.0);
    EXPECT_EQ(scene.nodes[square.channels[0].node].weights.size(), 2u);
    // The weights reach the vertices: at 2 s the cube is squashed ("thin" target), so its
    // posed bounds differ from the rest pose's.
    scene.updateWorldTransforms();
    ASSERT_TRUE(scene.meshInstances[0].deformed);
    EXPECT_FALSE(scene.meshInstances[0].worldBounds == rest);
}

// --- Bad input ---------------------------------------------------------------------------

using Edit = std::function<void(GltfBuilder&)>;
struct BadAnimation {
    std::string name;
    Edit edit;
    std::vector<std::string> message;  // the parts it must contain; the first is the file
};
void PrintTo(const BadAnimation& c, std::ostream* out) { *out << c.name; }

// Points samplers[s]'s input (or output) at a new FLOAT accessor holding `values`.
Edit samplerData(int s, const char* which, std::vector<float> values, std::size_t components, const char* type) {
    return [=](GltfBuilder& b) { animation(b)["samplers"][s][which] = b.addFloats(values, components, type); };
}
Edit set(const char* pointer, const json& value) {
    return [pointer = json::json_pointer(pointer), value](GltfBuilder& b) { b.doc[pointer] = value; };
}

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
const std::string kAnim = "animations[0] 'SlideTurnGrow'";

const BadAnimation kCases[] = {
    {"OutputCountDisagreesWithInput", set("/accessors/3/count", 1),
     {"count.gltf", kAnim + ".samplers[0]", "output accessors[3] has 1 elements, but 2 key times need 2 (1 per key)"}},
    {"CubicSplineWithoutTangents", set("/animations/0/samplers/0/interpolation", "CUBICSPLINE"),
     {"cubic.gltf", kAnim + ".samplers[0]", "has 2 elements, but 2 key times need 6 (3 per key)"}},
    {"TimesNotIncreasing", samplerData(0, "input", {1.0f, 0.5f}, 1, "SCALAR"),
     {"order.gltf", kAnim + ".samplers[0]", "must increase strictly, but key 1 (0.5 s) follows key 0 (1 s)"}},
    {"TimesRepeated", samplerData(0, "input", {0.5f, 0.5f}, 1, "SCALAR"),
     {"repeat.gltf", kAnim + ".samplers[0]", "key 1 (0.5 s) follows key 0 (0.5 s)"}},
    {"TimeBeforeZero", samplerData(0, "input", {-1.0f, 1.0f}, 1, "SCALAR"),
     {"negative.gltf", kAnim + ".samplers[0]", "input key 0 is at -1 s, before 0"}},
    {"TimeNaN", samplerData(0, "input", {0.0f, kNan}, 1, "SCALAR"),
     {"nantime.gltf", "used as input of " + kAnim + ".samplers[0]", "not a finite number"}},
    {"OutputInfinite", samplerData(0, "output", {0, 0, 0, kInf, 0, 0}, 3, "VEC3"),
     {"inf.gltf", "used as output of " + kAnim + ".samplers[0]", "element 1", "not a finite number"}},
    // An out-tangent of 1e37 over 1000 s may reach 1e37 * 1000 * 4/27 = 1.5e39 > FLT_MAX.
    {"CubicSplineLeavesFloatRange",
     [](GltfBuilder& b) {
         samplerData(2, "input", {0.0f, 1000.0f}, 1, "SCALAR")(b);
         samplerData(2, "output", {0, 0, 0, 1, 1, 1, 1e37f, 0, 0, 0, 0, 0, 3, 3, 3, 0, 0, 0}, 3, "VEC3")(b);
     },
     {"range.gltf", kAnim + ".samplers[2]", "CUBICSPLINE between keys 0 and 1 may reach", "beyond float range"}},
    {"RotationOutputIsVec3", samplerData(1, "output", {0, 0, 0, 0, 0, 1}, 3, "VEC3"),
     {"vec3.gltf", "used as output of " + kAnim + ".samplers[1]", "must be VEC4"}},
    {"ZeroQuaternionKey", samplerData(1, "output", {0, 0, 0, 1, 0, 0, 0, 0}, 4, "VEC4"),
     {"zeroq.gltf", kAnim + ".samplers[1]", "output key 1 is a zero quaternion"}},
    {"InputAccessorMissing", set("/animations/0/samplers/2/input", 99),
     {"noinput.gltf", kAnim + ".samplers[2]", "input accessor 99 does not exist"}},
    {"InterpolationUnknown", set("/animations/0/samplers/0/interpolation", "SMOOTH"),
     {"smooth.gltf", kAnim + ".samplers[0]", "interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE"}},
    {"TargetNodeMissing", set("/animations/0/channels/0/target/node", 7),
     {"nonode.gltf", kAnim + ".channels[0]", "target.node 7 does not exist (there are 1)"}},
    {"SamplerMissing", set("/animations/0/channels/2/sampler", 5),
     {"nosampler.gltf", kAnim + ".channels[2]", "sampler 5 does not exist (the animation has 3)"}},
    {"PathUnknown", set("/animations/0/channels/0/target/path", "skew"),
     {"skew.gltf", kAnim + ".channels[0]", "target.path 'skew' is not translation, rotation, scale or weights"}},
    {"TargetTwice", set("/animations/0/channels/2/target/path", "translation"),
     {"twice.gltf", kAnim + ".channels[2]", "targets translation of nodes[0] 'Quad', which an earlier channel"}},
    {"NodeGivenByMatrix", set("/nodes/0/matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
     {"matrix.gltf", kAnim + ".channels[0]", "targets nodes[0] 'Quad', which is given by a matrix"}},
    {"WeightsWithoutMorphTargets", set("/animations/0/channels/0/target/path", "weights"),
     {"weights.gltf", kAnim + ".channels[0]", "animates the weights of nodes[0] 'Quad', which has no morph targets"}},
    {"NoChannels", set("/animations/0/channels", json::array()),
     {"empty.gltf", kAnim, "channels is missing or empty"}},
    // tinygltf 2.7.0 refuses this before our reader sees it; its message names the field.
    {"TargetNodeAbsent", [](GltfBuilder& b) { animation(b)["channels"][1]["target"].erase("node"); },
     {"nodeless.gltf", "`node` field is missing in animation.channels.target"}},
    {"SamplerIndexNotAnInteger", set("/animations/0/channels/0/sampler", -1),
     {"minus.gltf", "animations[0].channels[0].sampler", "is not a non-negative integer"}},
};

class BadAnimationTest : public ::testing::TestWithParam<BadAnimation> {};

TEST_P(BadAnimationTest, IsRefusedNamingFileObjectAndReason) {
    const BadAnimation& c = GetParam();
    TempDir dir;
    GltfBuilder b = animatedQuad();
    c.edit(b);
    expectLoadError(b.writeGltf(dir.path(), fs::path(c.message.at(0)).stem().string()), c.message);
}

INSTANTIATE_TEST_SUITE_P(GltfAnimations, BadAnimationTest, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<BadAnimation>& info) { return info.param.name; });

} // namespace
