#include "GltfLights.h"

#include "GltfLightsShadows.h"

#include <cmath>
#include <numbers>
#include <set>

namespace engine::gltf {

namespace {

constexpr const char* kExtension = "KHR_lights_punctual";

// Reads one light object; every message names the light.
class LightReader {
public:
    LightReader(const LoadContext& context, const nlohmann::json& json, std::size_t index)
        : context_(context), json_(json) {
        object_ = std::string(kExtension) + "." + indexed("lights", index);
        if (!json.is_object()) context.fail(object_, "is not an object");
        if (const auto name = json.find("name"); name != json.end()) {
            if (!name->is_string()) context.fail(object_, "name is not a string");
            light_.name = name->get<std::string>();
            object_ = withName(object_, light_.name);
        }
    }

    Light read() {
        warnAboutUnknownKeys();
        readType();
        if (const auto color = json_.find("color"); color != json_.end()) light_.color = readColor(*color);
        light_.intensity = static_cast<float>(number("intensity", light_.intensity, 0.0, Bound::Inclusive));
        readRange();
        readSpot();
        const JsonFields fields(context_, object_, json_, "");
        light_.castShadows = readLightsShadows(fields, ShadowFlagsOwner::Light).castShadows;
        if (const auto extras = json_.find("extras"); extras != json_.end()) {
            if (!extras->is_object()) context_.fail(object_, "extras is not an object");
            light_.extras = *extras;
        }
        return light_;
    }

private:
    enum class Bound { Inclusive, Exclusive };

    void warnAboutUnknownKeys() const {
        static const std::set<std::string> known{"type", "name", "color", "intensity", "range", "spot",
                                                 "extensions", "extras"};
        for (const auto& [key, value] : json_.items())
            if (!known.count(key)) context_.warn(object_, "unknown property '" + key + "' is ignored");
    }

    void readType() {
        const auto type = json_.find("type");
        if (type == json_.end() || !type->is_string()) context_.fail(object_, "type is missing or not a string");
        const std::string text = type->get<std::string>();
        if (text == "directional") light_.type = Light::Type::Directional;
        else if (text == "point") light_.type = Light::Type::Point;
        else if (text == "spot") light_.type = Light::Type::Spot;
        else context_.fail(object_, "type '" + text + "' is not directional, point or spot");
    }

    glm::vec3 readColor(const nlohmann::json& color) const {
        if (!color.is_array() || color.size() != 3) context_.fail(object_, "color is not an array of 3 numbers");
        glm::vec3 result;
        for (int c = 0; c < 3; ++c) {
            if (!color[c].is_number()) context_.fail(object_, "color is not an array of 3 numbers");
            const double value = color[c].get<double>();
            if (!std::isfinite(value) || value < 0.0)
                context_.fail(object_, "color[" + std::to_string(c) + "] " + formatNumber(value) +
                                           " is not a finite number >= 0");
            result[c] = static_cast<float>(value);
        }
        return result;
    }

    // The number under `key` (or `fallback` when absent), finite and above `minimum`.
    double number(const char* key, double fallback, double minimum, Bound bound,
                  const nlohmann::json* from = nullptr, const std::string& prefix = "") const {
        const nlohmann::json& json = from ? *from : json_;
        const auto value = json.find(key);
        if (value == json.end()) return fallback;
        const std::string name = prefix + key;
        if (!value->is_number()) context_.fail(object_, name + " is not a number");
        const double result = value->get<double>();
        const bool aboveMinimum = bound == Bound::Inclusive ? result >= minimum : result > minimum;
        if (!std::isfinite(result) || !aboveMinimum)
            context_.fail(object_, name + " " + formatNumber(result) + " is not a finite number " +
                                       (bound == Bound::Inclusive ? ">= " : "> ") + formatNumber(minimum));
        return result;
    }

    void readRange() {
        if (!json_.contains("range")) return;  // absent = infinite, stored as 0
        if (light_.type == Light::Type::Directional) {
            context_.warn(object_, "range is ignored for a directional light");
            return;
        }
        light_.range = number("range", 0.0, 0.0, Bound::Exclusive);
    }

    void readSpot() {
        const auto spot = json_.find("spot");
        if (light_.type != Light::Type::Spot) {
            if (spot != json_.end()) context_.warn(object_, "spot is ignored for a light that is not a spot");
            return;
        }
        if (spot == json_.end() || !spot->is_object()) context_.fail(object_, "spot is missing or not an object");
        light_.outerConeAngle = number("outerConeAngle", light_.outerConeAngle, 0.0, Bound::Exclusive, &*spot, "spot.");
        light_.innerConeAngle = number("innerConeAngle", light_.innerConeAngle, 0.0, Bound::Inclusive, &*spot, "spot.");
        if (light_.outerConeAngle > std::numbers::pi / 2)
            context_.fail(object_, "spot.outerConeAngle " + formatNumber(light_.outerConeAngle) +
                                       " is more than pi/2");
        if (light_.innerConeAngle >= light_.outerConeAngle)
            context_.fail(object_, "spot.innerConeAngle " + formatNumber(light_.innerConeAngle) +
                                       " is not below outerConeAngle " + formatNumber(light_.outerConeAngle));
    }

    const LoadContext& context_;
    const nlohmann::json& json_;
    std::string object_;
    Light light_;
};

} // namespace

std::vector<Light> readPunctualLights(const LoadContext& context, const nlohmann::json& document) {
    std::vector<Light> lights;
    const auto extensions = document.find("extensions");
    if (extensions == document.end() || !extensions->is_object()) return lights;
    const auto extension = extensions->find(kExtension);
    if (extension == extensions->end()) return lights;
    if (!extension->is_object()) context.fail(std::string("extensions.") + kExtension, "is not an object");
    const auto list = extension->find("lights");
    if (list == extension->end()) return lights;
    if (!list->is_array()) context.fail(std::string(kExtension) + ".lights", "is not an array");
    for (std::size_t i = 0; i < list->size(); ++i) lights.push_back(LightReader(context, (*list)[i], i).read());
    return lights;
}

int nodeLightIndex(const LoadContext& context, const tinygltf::Node& node, std::size_t nodeIndex) {
    const auto extension = node.extensions.find(kExtension);
    if (extension == node.extensions.end()) return -1;
    const std::string object = indexedNamed("nodes", nodeIndex, node.name);
    const tinygltf::Value& value = extension->second;
    if (!value.IsObject() || !value.Has("light") || !value.Get("light").IsInt())
        context.fail(object, std::string("extensions.") + kExtension + ".light is missing or not an integer");
    return value.Get("light").GetNumberAsInt();
}

} // namespace engine::gltf
