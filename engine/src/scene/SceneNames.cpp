#include "engine/scene/SceneNames.h"

#include <algorithm>
#include <charconv>

namespace engine {

namespace {

// One rule for lights and cameras: the instance lists differ only in their types.
template <typename Instance, typename Object>
std::string instanceName(const std::vector<Instance>& instances, const std::vector<Object>& objects,
                         int Instance::*objectIndex, const std::vector<Node>& nodes, int instance,
                         const char* kind) {
    const Instance& placed = instances.at(instance);
    if (const std::string& own = objects[placed.*objectIndex].name; !own.empty()) return own;
    if (const std::string& node = nodes[placed.node].name; !node.empty()) return node;
    return std::string(kind) + " " + std::to_string(instance + 1);
}

int instanceByNumber(const std::string& text, std::size_t count) {
    std::size_t number = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) return -1;
    return number >= 1 && number <= count ? static_cast<int>(number - 1) : -1;
}

template <typename NameOf>
std::string describeInstances(std::size_t count, const char* kinds, NameOf nameOf) {
    if (count == 0) return std::string("the scene has no ") + kinds;
    constexpr std::size_t kListed = 10;  // a CAD import can place hundreds
    std::string text = std::string("the scene's ") + kinds + ": ";
    for (std::size_t i = 0; i < std::min(count, kListed); ++i)
        text += (i ? ", " : "") + std::to_string(i + 1) + " " + nameOf(static_cast<int>(i));
    if (count > kListed) text += ", ... (" + std::to_string(count) + " in all)";
    return text;
}

} // namespace

const char* toString(Light::Type type) {
    switch (type) {
    case Light::Type::Directional: return "directional";
    case Light::Type::Spot: return "spot";
    case Light::Type::Point: return "point";
    }
    return "unknown";
}

const char* toString(Camera::Type type) {
    return type == Camera::Type::Perspective ? "perspective" : "orthographic";
}

std::string lightInstanceName(const Scene& scene, int instance) {
    return instanceName(scene.lightInstances, scene.lights, &LightInstance::light, scene.nodes, instance, "light");
}

std::string cameraInstanceName(const Scene& scene, int instance) {
    return instanceName(scene.cameraInstances, scene.cameras, &CameraInstance::camera, scene.nodes, instance,
                        "camera");
}

int findLightInstanceByNameOrNumber(const Scene& scene, const std::string& text) {
    const int named = scene.findLightInstance(text);
    return named >= 0 ? named : instanceByNumber(text, scene.lightInstances.size());
}

int findCameraInstanceByNameOrNumber(const Scene& scene, const std::string& text) {
    const int named = scene.findCameraInstance(text);
    return named >= 0 ? named : instanceByNumber(text, scene.cameraInstances.size());
}

std::string describeLightInstances(const Scene& scene) {
    return describeInstances(scene.lightInstances.size(), "lights",
                             [&](int i) { return lightInstanceName(scene, i); });
}

std::string lightsPastTheLimit(const Scene& scene, int limit) {
    const int count = static_cast<int>(scene.lightInstances.size());
    if (count <= limit) return "";
    constexpr int kListed = 10;
    std::string text = "the scene has " + std::to_string(count) + " lights; only the first " +
                       std::to_string(limit) + " are rendered, not: ";
    for (int i = limit; i < std::min(count, limit + kListed); ++i)
        text += (i > limit ? ", " : "") + std::to_string(i + 1) + " " + lightInstanceName(scene, i);
    if (count - limit > kListed) text += ", ...";
    return text;
}

std::string describeCameraInstances(const Scene& scene) {
    return describeInstances(scene.cameraInstances.size(), "cameras",
                             [&](int i) { return cameraInstanceName(scene, i); });
}

} // namespace engine
