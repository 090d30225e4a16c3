#include "GltfAnimations.h"

#include "GltfAccessors.h"
#include "GltfJsonFields.h"
#include "GltfValidation.h"

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace engine::gltf {

namespace {

std::optional<AnimationPath> pathNamed(const std::string& text) {
    if (text == "translation") return AnimationPath::Translation;
    if (text == "rotation") return AnimationPath::Rotation;
    if (text == "scale") return AnimationPath::Scale;
    if (text == "weights") return AnimationPath::Weights;
    return std::nullopt;
}

std::optional<Interpolation> interpolationNamed(const std::string& text) {
    if (text == "LINEAR") return Interpolation::Linear;
    if (text == "STEP") return Interpolation::Step;
    if (text == "CUBICSPLINE") return Interpolation::CubicSpline;
    return std::nullopt;
}

// What a sampler's output must hold, fixed by the channel(s) that use it.
struct SamplerUse {
    AnimationPath path;
    std::size_t components;  // per key value (morph target count for weights)
    bool operator==(const SamplerUse&) const = default;
};

// Reads one animation; every message names it and the channel or sampler at fault.
class AnimationReader {
public:
    AnimationReader(const LoadContext& context, const tinygltf::Model& model, const nlohmann::json& json,
                    std::size_t index)
        : context_(context), model_(model), json_(json) {
        const auto name = json.find("name");  // its type is checked by checkPropertyTypes
        if (name != json.end()) animation_.name = name->get<std::string>();
        object_ = indexedNamed("animations", index, animation_.name);
    }

    Animation read() {
        const nlohmann::json& samplers = requiredArray("samplers");
        const nlohmann::json& channels = requiredArray("channels");
        std::vector<std::optional<SamplerUse>> uses(samplers.size());
        std::set<std::pair<int, AnimationPath>> targets;
        for (std::size_t c = 0; c < channels.size(); ++c) readChannel(channels[c], c, samplers.size(), uses, targets);
        bool anyKeys = false;
        for (std::size_t s = 0; s < samplers.size(); ++s) {
            AnimationSampler sampler;
            if (uses[s]) {
                sampler = readSampler(samplers[s], s, *uses[s]);
                animation_.startTime = anyKeys ? std::min(animation_.startTime, sampler.times.front()) : sampler.times.front();
                animation_.endTime = anyKeys ? std::max(animation_.endTime, sampler.times.back()) : sampler.times.back();
                anyKeys = true;
            } else {
                context_.warn(samplerObject(s), "no channel uses it; ignored");
            }
            animation_.samplers.push_back(std::move(sampler));
        }
        return std::move(animation_);
    }

private:
    const nlohmann::json& requiredArray(const char* key) const {
        const auto array = json_.find(key);  // an array when present: checkPropertyTypes
        if (array == json_.end() || array->empty())
            context_.fail(object_, std::string(key) + " is missing or empty (glTF requires at least one)");
        return *array;
    }

    std::string channelObject(std::size_t c) const { return object_ + "." + indexed("channels", c); }
    std::string samplerObject(std::size_t s) const { return object_ + "." + indexed("samplers", s); }

    void readChannel(const nlohmann::json& json, std::size_t c, std::size_t samplerCount,
                     std::vector<std::optional<SamplerUse>>& uses, std::set<std::pair<int, AnimationPath>>& targets) {
        const std::string object = channelObject(c);
        const JsonFields fields(context_, object, json, "");
        const std::optional<std::uint64_t> sampler = fields.index("sampler");
        if (!sampler) context_.fail(object, "sampler is missing");
        if (*sampler >= samplerCount)
            context_.fail(object, "sampler " + std::to_string(*sampler) + " does not exist (the animation has " +
                                      std::to_string(samplerCount) + ")");
        if (!fields.has("target")) context_.fail(object, "target is missing");
        const JsonFields target = fields.child("target");
        const nlohmann::json* pathJson = target.find("path");
        if (!pathJson) context_.fail(object, "target.path is missing");
        const std::optional<AnimationPath> path = pathNamed(pathJson->get<std::string>());
        if (!path)
            context_.fail(object, "target.path '" + pathJson->get<std::string>() +
                                      "' is not translation, rotation, scale or weights");
        const std::optional<std::uint64_t> node = target.index("node");
        // glTF lets an extension (KHR_animation_pointer) stand in for target.node; tinygltf
        // 2.7.0 refuses such files before we get here, and we support none.
        if (!node) context_.fail(object, "target.node is missing (extension targets are not supported)");
        if (*node >= model_.nodes.size())
            context_.fail(object, "target.node " + std::to_string(*node) + " does not exist (there are " +
                                      std::to_string(model_.nodes.size()) + ")");
        const int nodeIndex = static_cast<int>(*node);
        const tinygltf::Node& targetNode = model_.nodes[nodeIndex];
        const std::string nodeName = indexedNamed("nodes", nodeIndex, targetNode.name);
        if (targetNode.matrix.size() == 16)
            context_.fail(object, "targets " + nodeName + ", which is given by a matrix (glTF animates only "
                                      "translation, rotation and scale)");
        if (!targets.insert({nodeIndex, *path}).second)
            context_.fail(object, "targets " + pathJson->get<std::string>() + " of " + nodeName +
                                      ", which an earlier channel of the animation already targets");

        const SamplerUse use{*path, componentsFor(object, *path, targetNode, nodeName)};
        std::optional<SamplerUse>& samplerUse = uses[*sampler];
        if (samplerUse && !(*samplerUse == use))
            context_.fail(object, "uses " + samplerObject(*sampler) + " for " + pathJson->get<std::string>() +
                                      ", but another channel uses it for values of another size");
        samplerUse = use;
        animation_.channels.push_back({nodeIndex, *path, static_cast<int>(*sampler)});
    }

    std::size_t componentsFor(const std::string& object, AnimationPath path, const tinygltf::Node& node,
                              const std::string& nodeName) const {
        switch (path) {
        case AnimationPath::Translation:
        case AnimationPath::Scale: return 3;
        case AnimationPath::Rotation: return 4;
        case AnimationPath::Weights: break;
        }
        // All primitives of a mesh have the same number of targets (glTF 2.0 3.7.2.2).
        const std::size_t targetCount =
            node.mesh >= 0 && !model_.meshes[node.mesh].primitives.empty()
                ? model_.meshes[node.mesh].primitives[0].targets.size()
                : 0;
        if (targetCount == 0) context_.fail(object, "animates the weights of " + nodeName + ", which has no morph targets");
        return targetCount;
    }

    AnimationSampler readSampler(const nlohmann::json& json, std::size_t s, const SamplerUse& use) const {
        const std::string object = samplerObject(s);
        const JsonFields fields(context_, object, json, "");
        AnimationSampler sampler;
        if (const nlohmann::json* text = fields.find("interpolation")) {
            const std::optional<Interpolation> interpolation = interpolationNamed(text->get<std::string>());
            if (!interpolation)
                context_.fail(object, "interpolation '" + text->get<std::string>() + "' is not LINEAR, STEP or CUBICSPLINE");
            sampler.interpolation = *interpolation;
        }
        const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
        sampler.times = readFloatComponents(context_, model_, accessorIndex(fields, "input"),
                                            {"input of " + object, TINYGLTF_TYPE_SCALAR, AccessorUse::Components::Float});
        checkTimes(object, sampler.times, cubic);

        const bool vec3 = use.path == AnimationPath::Translation || use.path == AnimationPath::Scale;
        const AccessorUse outputUse{
            "output of " + object,
            vec3 ? TINYGLTF_TYPE_VEC3 : use.path == AnimationPath::Rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_SCALAR,
            vec3 ? AccessorUse::Components::Float : AccessorUse::Components::FloatOrAnyNormalized};
        const int output = accessorIndex(fields, "output");
        sampler.values = readFloatComponents(context_, model_, output, outputUse);
        sampler.components = use.components;
        const std::size_t elementsPerKey = cubic ? 3 : 1;
        const std::size_t needed = sampler.times.size() * elementsPerKey * use.components;
        if (sampler.values.size() != needed) {
            const std::size_t perElement = use.path == AnimationPath::Weights ? 1 : use.components;
            context_.fail(object, "output " + indexed("accessors", output) + " has " +
                                      std::to_string(sampler.values.size() / perElement) + " elements, but " +
                                      std::to_string(sampler.times.size()) + " key times need " +
                                      std::to_string(needed / perElement) + " (" +
                                      std::to_string(needed / perElement / sampler.times.size()) + " per key)");
        }
        if (cubic) checkSplineRange(object, sampler);
        if (use.path == AnimationPath::Rotation) checkRotations(object, sampler, cubic);
        return sampler;
    }

    int accessorIndex(const JsonFields& fields, const char* key) const {
        const std::optional<std::uint64_t> index = fields.index(key);
        if (!index) fields.fail(key, "is missing");
        if (*index >= model_.accessors.size())
            fields.fail(key, "accessor " + std::to_string(*index) + " does not exist (there are " +
                                 std::to_string(model_.accessors.size()) + ")");
        return static_cast<int>(*index);
    }

    // glTF 2.0: times are non-negative and strictly increasing; a cubic spline needs two keys.
    void checkTimes(const std::string& object, const std::vector<float>& times, bool cubic) const {
        if (times.front() < 0.0f) context_.fail(object, "input key 0 is at " + formatNumber(times.front()) + " s, before 0");
        for (std::size_t k = 1; k < times.size(); ++k)
            if (!(times[k] > times[k - 1]))
                context_.fail(object, "input key times must increase strictly, but key " + std::to_string(k) + " (" +
                                          formatNumber(times[k]) + " s) follows key " + std::to_string(k - 1) + " (" +
                                          formatNumber(times[k - 1]) + " s)");
        if (cubic && times.size() < 2) context_.fail(object, "CUBICSPLINE needs at least 2 keys, input has 1");
    }

    // Between keys k and k+1 a spline component is at most |v_k| + |v_k+1| + td (|b_k| +
    // |a_k+1|) * 4/27 (the Hermite basis: h00 + h01 = 1, |h10|, |h11| <= 4/27 on [0, 1]).
    // Finite keys with huge tangents or intervals could still leave float: refused, so a
    // sampled pose is always finite.
    void checkSplineRange(const std::string& object, const AnimationSampler& sampler) const {
        const std::size_t n = sampler.components;
        for (std::size_t k = 0; k + 1 < sampler.times.size(); ++k) {
            const double td = double(sampler.times[k + 1]) - sampler.times[k];
            const float* key = sampler.values.data() + 3 * k * n;
            const float* next = key + 3 * n;
            for (std::size_t c = 0; c < n; ++c) {
                const double bound = std::abs(double(key[n + c])) + std::abs(double(next[n + c])) +
                                     td * (std::abs(double(key[2 * n + c])) + std::abs(double(next[c]))) * 4.0 / 27.0;
                if (bound > std::numeric_limits<float>::max())
                    context_.fail(object, "CUBICSPLINE between keys " + std::to_string(k) + " and " +
                                              std::to_string(k + 1) + " may reach " + formatNumber(bound) +
                                              ", beyond float range (tangents too large for the interval)");
            }
        }
    }

    // Rotation keys must be rotations: a zero quaternion has no direction to normalize to.
    // STEP and LINEAR keys are normalized here (exporters round them to float or to
    // normalized integers); CUBICSPLINE values are normalized after interpolation.
    void checkRotations(const std::string& object, AnimationSampler& sampler, bool cubic) const {
        for (std::size_t k = 0; k < sampler.times.size(); ++k) {
            float* key = sampler.values.data() + (cubic ? 3 * k + 1 : k) * 4;
            const double length = std::sqrt(double(key[0]) * key[0] + double(key[1]) * key[1] +
                                            double(key[2]) * key[2] + double(key[3]) * key[3]);
            if (length < 1e-6) context_.fail(object, "output key " + std::to_string(k) + " is a zero quaternion");
            if (!cubic)
                for (int c = 0; c < 4; ++c) key[c] = static_cast<float>(key[c] / length);
        }
    }

    const LoadContext& context_;
    const tinygltf::Model& model_;
    const nlohmann::json& json_;
    std::string object_;
    Animation animation_;
};

} // namespace

std::vector<Animation> readAnimations(const LoadContext& context, const tinygltf::Model& model,
                                      const nlohmann::json& document) {
    std::vector<Animation> animations;
    const auto list = document.find("animations");  // an array of objects: checkPropertyTypes
    if (list == document.end()) return animations;
    for (std::size_t i = 0; i < list->size(); ++i)
        animations.push_back(AnimationReader(context, model, (*list)[i], i).read());
    return animations;
}

} // namespace engine::gltf
