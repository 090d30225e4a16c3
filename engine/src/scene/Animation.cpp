// Keyframe sampling as glTF 2.0 Appendix C defines it, and posing nodes from it.
#include "engine/scene/Animation.h"

#include "engine/scene/Scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace engine {

namespace {

glm::dquat quaternionAt(const float* xyzw) {
    return glm::dquat(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);  // glm takes w first
}

void storeQuaternion(const glm::dquat& q, float* xyzw) {
    xyzw[0] = static_cast<float>(q.x);
    xyzw[1] = static_cast<float>(q.y);
    xyzw[2] = static_cast<float>(q.z);
    xyzw[3] = static_cast<float>(q.w);
}

// Spherical interpolation along the shorter arc: q and -q are the same rotation, and the
// spec asks for the shortest path. Near-parallel keys fall back to a normalized lerp,
// where slerp's 1/sin(angle) would lose every digit.
glm::dquat slerpShortest(glm::dquat a, const glm::dquat& b, double s) {
    double cosine = glm::dot(a, b);
    if (cosine < 0.0) {
        a = -a;
        cosine = -cosine;
    }
    if (cosine > 1.0 - 1e-9) return glm::normalize(a * (1.0 - s) + b * s);
    const double angle = std::acos(cosine);
    const double sine = std::sin(angle);
    return glm::normalize(a * (std::sin((1.0 - s) * angle) / sine) + b * (std::sin(s * angle) / sine));
}

// Appendix C: p(s) = (2s³-3s²+1)v_k + td(s³-2s²+s)b_k + (-2s³+3s²)v_k+1 + td(s³-s²)a_k+1,
// with b_k key k's out-tangent and a_k+1 key k+1's in-tangent, each scaled by the interval td.
void cubicSpline(const AnimationSampler& sampler, std::size_t k, double s, double td, float* out) {
    const std::size_t n = sampler.components;
    const float* keyK = sampler.values.data() + 3 * k * n;         // a_k, v_k, b_k
    const float* keyNext = sampler.values.data() + 3 * (k + 1) * n;  // a_k+1, v_k+1, b_k+1
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = td * (s3 - 2 * s2 + s);
    const double h01 = -2 * s3 + 3 * s2, h11 = td * (s3 - s2);
    for (std::size_t c = 0; c < n; ++c)
        out[c] = static_cast<float>(h00 * keyK[n + c] + h10 * keyK[2 * n + c] + h01 * keyNext[n + c] +
                                    h11 * keyNext[c]);
}

} // namespace

std::vector<float> sampleAnimation(const AnimationSampler& sampler, AnimationPath path, double seconds) {
    const std::size_t n = sampler.components;
    const std::vector<float>& times = sampler.times;
    assert(!times.empty() && n > 0);
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    // Element e of key k: CUBICSPLINE stores (in-tangent, value, out-tangent) per key.
    const auto keyValue = [&](std::size_t k) { return sampler.values.data() + (cubic ? 3 * k + 1 : k) * n; };

    std::vector<float> out(n);
    const auto copyKey = [&](std::size_t k) { std::copy_n(keyValue(k), n, out.begin()); };
    if (seconds <= times.front()) {
        copyKey(0);
    } else if (seconds >= times.back()) {
        copyKey(times.size() - 1);
    } else {
        // k: the last key at or before `seconds`; k + 1 exists because seconds < times.back().
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(times.begin(), times.end(), seconds, [](double t, float key) { return t < key; }) -
            times.begin() - 1);
        const double td = static_cast<double>(times[k + 1]) - times[k];
        const double s = (seconds - times[k]) / td;
        switch (sampler.interpolation) {
        case Interpolation::Step: copyKey(k); break;
        case Interpolation::Linear:
            if (path == AnimationPath::Rotation) {
                storeQuaternion(slerpShortest(quaternionAt(keyValue(k)), quaternionAt(keyValue(k + 1)), s), out.data());
            } else {
                for (std::size_t c = 0; c < n; ++c)
                    out[c] = static_cast<float>((1.0 - s) * keyValue(k)[c] + s * keyValue(k + 1)[c]);
            }
            break;
        case Interpolation::CubicSpline:
            cubicSpline(sampler, k, s, td, out.data());
            // A spline between unit quaternions is not unit length; one passing through
            // zero (keys q and -q with flat tangents) has no direction: keep key k there.
            if (path == AnimationPath::Rotation && glm::length(quaternionAt(out.data())) < 1e-6) copyKey(k);
            break;
        }
    }
    // STEP and LINEAR keys were normalized at load and slerp keeps unit length; CUBICSPLINE
    // values (keys included) are normalized here.
    if (path == AnimationPath::Rotation && cubic) storeQuaternion(glm::normalize(quaternionAt(out.data())), out.data());
    return out;
}

void poseAnimation(Scene& scene, const Animation& animation, double seconds) {
    for (const AnimationChannel& channel : animation.channels) {
        assert(channel.node >= 0 && static_cast<std::size_t>(channel.node) < scene.nodes.size());
        Node& node = scene.nodes[channel.node];
        const std::vector<float> value = sampleAnimation(animation.samplers[channel.sampler], channel.path, seconds);
        switch (channel.path) {
        case AnimationPath::Translation: node.translation = glm::dvec3(value[0], value[1], value[2]); break;
        case AnimationPath::Rotation: node.rotation = quaternionAt(value.data()); break;
        case AnimationPath::Scale: node.scale = glm::dvec3(value[0], value[1], value[2]); break;
        case AnimationPath::Weights: node.weights = value; break;
        }
        node.local = node.trsMatrix();
    }
}

int findAnimation(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        if (scene.animations[i].name == name) return static_cast<int>(i);
    return -1;
}

} // namespace engine
