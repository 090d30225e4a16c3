#pragma once
// glTF animations as plain data, and their sampling (glTF 2.0 section 3.11 and Appendix C).
// The loader guarantees the invariants stated on each field, so sampling never fails.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace engine {

struct Scene;

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights };

struct AnimationSampler {
    Interpolation interpolation = Interpolation::Linear;
    // Key times in seconds: at least one, finite, >= 0, strictly increasing (CUBICSPLINE:
    // at least two).
    std::vector<float> times;
    // Finite values, `components` per element: one element per key (STEP, LINEAR), three per
    // key for CUBICSPLINE (in-tangent, value, out-tangent, as glTF stores them). Rotation
    // values of STEP and LINEAR samplers are unit quaternions (x, y, z, w); CUBICSPLINE
    // rotations are normalized after interpolation.
    std::vector<float> values;
    std::size_t components = 0;  // 3 translation/scale, 4 rotation, morph target count for weights
};

struct AnimationChannel {
    int node = -1;  // a valid index into Scene::nodes, a node without a matrix
    AnimationPath path = AnimationPath::Translation;
    int sampler = -1;  // a valid index into Animation::samplers, whose components fit `path`
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;  // no two share a (node, path)
    // The first and last key time over all samplers: the animation's time span.
    float startTime = 0.0f;
    float endTime = 0.0f;
};

// The sampler's value at `seconds` (sampler.components floats). Before the first key the
// first value holds, after the last key the last one (glTF leaves looping to the player).
// STEP holds key k on [t_k, t_k+1); LINEAR interpolates componentwise, except rotations,
// which are slerped along the shorter arc; CUBICSPLINE is the Hermite spline of Appendix C
// with tangents scaled by the key interval. Rotations come back normalized.
std::vector<float> sampleAnimation(const AnimationSampler& sampler, AnimationPath path, double seconds);

// Writes every channel's value at `seconds` into its node's translation / rotation / scale /
// weights and recomposes those nodes' local transforms. Nodes the animation does not target
// keep their transforms. Call Scene::updateWorldTransforms() afterwards.
void poseAnimation(Scene& scene, const Animation& animation, double seconds);

// The animation named `name`, else -1.
int findAnimation(const Scene& scene, const std::string& name);

} // namespace engine
