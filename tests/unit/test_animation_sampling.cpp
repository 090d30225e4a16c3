// Keyframe sampling (glTF 2.0 Appendix C) against values computed by hand in the comments,
// and posing a scene from an animation. No loader: samplers are built in code.
#include "engine/scene/Animation.h"
#include "engine/scene/Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using engine::AnimationPath;
using engine::AnimationSampler;
using engine::Interpolation;

// Sampling runs in double and returns float: 1e-6 is a few float ulps at the magnitudes
// below (|values| <= 8), far under any difference the cases are built to tell apart
// (the smallest, slerp against normalized lerp, is 7.7e-3).
constexpr float kTolerance = 1e-6f;

AnimationSampler sampler(Interpolation interpolation, std::vector<float> times, std::vector<float> values,
                         std::size_t components) {
    return {interpolation, std::move(times), std::move(values), components};
}

void expectValues(const std::vector<float>& actual, const std::vector<float>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(actual[i], expected[i], kTolerance) << "component " << i;
}

// (x, y, z, w) of a rotation by `degrees` about +Z.
std::vector<float> aboutZ(double degrees) {
    const double half = degrees * std::numbers::pi / 360.0;
    return {0.0f, 0.0f, static_cast<float>(std::sin(half)), static_cast<float>(std::cos(half))};
}

TEST(AnimationSampling, StepHoldsEachKeyUntilTheNextAndClampsOutside) {
    const AnimationSampler step = sampler(Interpolation::Step, {0.5f, 1.0f, 2.0f}, {0, 0, 0, 1, 2, 3, 5, 5, 5}, 3);
    expectValues(engine::sampleAnimation(step, AnimationPath::Translation, 0.0), {0, 0, 0});  // before the first key
    expectValues(engine::sampleAnimation(step, AnimationPath::Translation, 0.99), {0, 0, 0});
    expectValues(engine::sampleAnimation(step, AnimationPath::Translation, 1.0), {1, 2, 3});  // a key time takes its key
    expectValues(engine::sampleAnimation(step, AnimationPath::Translation, 1.5), {1, 2, 3});
    expectValues(engine::sampleAnimation(step, AnimationPath::Translation, 7.0), {5, 5, 5});  // after the last
}

TEST(AnimationSampling, LinearInterpolatesVectorsComponentwise) {
    const AnimationSampler linear = sampler(Interpolation::Linear, {1.0f, 3.0f}, {0, 0, 0, 4, 8, -4}, 3);
    // t = 1.5 is s = (1.5 - 1) / 2 = 0.25 of the way: 0.25 * (4, 8, -4).
    expectValues(engine::sampleAnimation(linear, AnimationPath::Scale, 1.5), {1, 2, -1});
}

TEST(AnimationSampling, LinearRotationIsASlerpNotANormalizedLerp) {
    std::vector<float> keys = aboutZ(0);
    const std::vector<float> quarter = aboutZ(90);
    keys.insert(keys.end(), quarter.begin(), quarter.end());
    const AnimationSampler linear = sampler(Interpolation::Linear, {0.0f, 1.0f}, keys, 4);
    // A quarter of the way along a 90 degree turn is 22.5 degrees: z = sin(11.25 deg) =
    // 0.195090. A normalized lerp would give 0.187366 (21.6 degrees).
    expectValues(engine::sampleAnimation(linear, AnimationPath::Rotation, 0.25), aboutZ(22.5));
}

TEST(AnimationSampling, LinearRotationTakesTheShorterArc) {
    // The second key is the 90 degree turn written as -q (the same rotation). The shorter
    // arc passes 45 degrees at the midpoint; the longer one would turn the other way
    // round (through -135 degrees).
    std::vector<float> keys = aboutZ(0);
    for (const float c : aboutZ(90)) keys.push_back(-c);
    const AnimationSampler linear = sampler(Interpolation::Linear, {0.0f, 1.0f}, keys, 4);
    std::vector<float> half = engine::sampleAnimation(linear, AnimationPath::Rotation, 0.5);
    if (half[3] < 0) for (float& c : half) c = -c;  // q and -q are one rotation
    expectValues(half, aboutZ(45));
}

// Keys at t = 1 and t = 3 (interval td = 2), per key (in-tangent a, value v, out-tangent b).
// Tangents that must not be used (a_0, b_1) are 100, so reading the wrong one shows.
AnimationSampler cubicTranslation() {
    return sampler(Interpolation::CubicSpline, {1.0f, 3.0f},
                   {
                       100, 100, 100,  // a_0 (unused between the keys)
                       0, 2, 0,        // v_0
                       1, 0, 0,        // b_0
                       0, -4, 0,       // a_1
                       1, 0, 8,        // v_1
                       100, 100, 100,  // b_1 (unused)
                   },
                   3);
}

TEST(AnimationSampling, CubicSplineScalesTangentsByTheKeyInterval) {
    // s = 0.5: h00 = 0.5, h10 = td*(s^3 - 2s^2 + s) = 2*0.125 = 0.25, h01 = 0.5,
    // h11 = td*(s^3 - s^2) = -0.25.  p = h00 v0 + h10 b0 + h01 v1 + h11 a1:
    // x = 0.25*1 + 0.5*1 = 0.75; y = 0.5*2 + (-0.25)(-4) = 2; z = 0.5*8 = 4.
    // (Unscaled tangents would give x = 0.625, y = 1.5.)
    expectValues(engine::sampleAnimation(cubicTranslation(), AnimationPath::Translation, 2.0), {0.75f, 2.0f, 4.0f});
    // s = 0.25: h00 = 0.84375, h10 = 0.28125, h01 = 0.15625, h11 = -0.09375:
    // x = 0.28125 + 0.15625 = 0.4375; y = 1.6875 + 0.375 = 2.0625; z = 1.25.
    expectValues(engine::sampleAnimation(cubicTranslation(), AnimationPath::Translation, 1.5), {0.4375f, 2.0625f, 1.25f});
}

TEST(AnimationSampling, CubicSplineClampsToTheKeyValuesNotTheirTangents) {
    expectValues(engine::sampleAnimation(cubicTranslation(), AnimationPath::Translation, 0.0), {0, 2, 0});
    expectValues(engine::sampleAnimation(cubicTranslation(), AnimationPath::Translation, 9.0), {1, 0, 8});
}

TEST(AnimationSampling, CubicSplineRotationIsNormalized) {
    // Flat tangents: at s = 0.5 the spline is 0.5 q0 + 0.5 q1, whose direction is the
    // 45 degree turn, of length cos(22.5 deg) = 0.92 before normalization.
    std::vector<float> keys;
    const std::vector<float> zero(4, 0.0f), q0 = aboutZ(0), q1 = aboutZ(90);
    for (const auto* part : {&zero, &q0, &zero, &zero, &q1, &zero}) keys.insert(keys.end(), part->begin(), part->end());
    const AnimationSampler cubic = sampler(Interpolation::CubicSpline, {0.0f, 1.0f}, keys, 4);
    expectValues(engine::sampleAnimation(cubic, AnimationPath::Rotation, 0.5), aboutZ(45));
}

TEST(AnimationSampling, WeightsSampleEveryMorphTarget) {
    const AnimationSampler linear = sampler(Interpolation::Linear, {0.0f, 2.0f}, {0, 1, 1, 0}, 2);
    expectValues(engine::sampleAnimation(linear, AnimationPath::Weights, 0.5), {0.25f, 0.75f});
}

// Two mesh nodes; an animation moves the first along +X.
engine::Scene twoBoxes() {
    engine::Scene scene;
    engine::Mesh mesh;
    mesh.bounds.extend(glm::dvec3(-1.0));
    mesh.bounds.extend(glm::dvec3(1.0));
    scene.meshes.push_back(mesh);
    scene.nodes.resize(2);
    scene.nodes[0].mesh = scene.nodes[1].mesh = 0;
    scene.nodes[1].translation = glm::dvec3(0, 5, 0);
    scene.nodes[1].local = scene.nodes[1].trsMatrix();
    scene.roots = {0, 1};
    engine::Animation slide;
    slide.samplers.push_back(sampler(Interpolation::Linear, {0.0f, 1.0f}, {0, 0, 0, 10, 0, 0}, 3));
    slide.channels.push_back({0, AnimationPath::Translation, 0});
    slide.endTime = 1.0f;
    scene.animations.push_back(slide);
    scene.updateWorldTransforms();
    return scene;
}

TEST(AnimationPose, MovesTheTargetedNodeAndItsBounds) {
    engine::Scene scene = twoBoxes();
    engine::poseAnimation(scene, scene.animations[0], 0.5);
    scene.updateWorldTransforms();
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.min.x, 4.0);  // -1 + 0.5 * 10
    EXPECT_DOUBLE_EQ(scene.meshInstances[0].worldBounds.max.x, 6.0);
    EXPECT_DOUBLE_EQ(scene.meshInstances[1].worldBounds.min.y, 4.0);  // untouched: 5 - 1
    EXPECT_DOUBLE_EQ(scene.worldBounds.max.x, 6.0);
}

TEST(AnimationPose, RevisionChangesExactlyForInstancesThatMoved) {
    engine::Scene scene = twoBoxes();
    const std::uint64_t moving = scene.meshInstances[0].revision, still = scene.meshInstances[1].revision;
    EXPECT_NE(moving, still);

    engine::poseAnimation(scene, scene.animations[0], 0.5);
    scene.updateWorldTransforms();
    const std::uint64_t moved = scene.meshInstances[0].revision;
    EXPECT_NE(moved, moving);
    EXPECT_NE(moved, still);
    EXPECT_EQ(scene.meshInstances[1].revision, still);

    // Posing at the same time again moves nothing.
    engine::poseAnimation(scene, scene.animations[0], 0.5);
    scene.updateWorldTransforms();
    EXPECT_EQ(scene.meshInstances[0].revision, moved);
    EXPECT_EQ(scene.meshInstances[1].revision, still);

    // Back to the start: revisions are never reused, so the instance gets a new one rather
    // than its first (Scene.h promises no more than "equal means unchanged since").
    engine::poseAnimation(scene, scene.animations[0], 0.0);
    scene.updateWorldTransforms();
    EXPECT_NE(scene.meshInstances[0].revision, moving);
    EXPECT_NE(scene.meshInstances[0].revision, moved);
}

} // namespace
