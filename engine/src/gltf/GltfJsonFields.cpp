#include "GltfJsonFields.h"

#include <cmath>
#include <limits>

namespace engine::gltf {

namespace {

const nlohmann::json kEmptyObject = nlohmann::json::object();

bool finiteAsFloat(double value) {
    return std::isfinite(value) && std::fabs(value) <= std::numeric_limits<float>::max();
}

} // namespace

const nlohmann::json& arrayElement(const nlohmann::json& parent, const char* array, std::size_t index) {
    static const nlohmann::json null;
    const auto list = parent.find(array);  // a non-object parent finds nothing
    if (list == parent.end() || !list->is_array() || index >= list->size()) return null;
    return (*list)[index];
}

JsonFields::JsonFields(const LoadContext& context, std::string object, const nlohmann::json& json, std::string path)
    : context_(&context), object_(std::move(object)), json_(json.is_null() ? &kEmptyObject : &json),
      path_(std::move(path)) {
    if (!json_->is_object()) context.fail(object_, (path_.empty() ? std::string("it") : path_) + " is not an object");
}

JsonFields JsonFields::child(const char* key) const {
    const nlohmann::json* value = find(key);
    if (value && !value->is_object()) fail(key, "is not an object");
    return JsonFields(*context_, object_, value ? *value : kEmptyObject, member(key));
}

std::optional<JsonFields> JsonFields::extension(const char* name) const {
    const nlohmann::json* extensions = find("extensions");
    if (!extensions) return std::nullopt;
    if (!extensions->is_object()) fail("extensions", "is not an object");
    const auto value = extensions->find(name);
    if (value == extensions->end()) return std::nullopt;
    const std::string path = member("extensions") + "." + name;
    if (!value->is_object()) context_->fail(object_, path + " is not an object");
    return JsonFields(*context_, object_, *value, path);
}

const nlohmann::json* JsonFields::find(const char* key) const {
    const auto value = json_->find(key);
    return value == json_->end() ? nullptr : &*value;
}

bool JsonFields::boolean(const char* key, bool fallback) const {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    if (!value->is_boolean()) fail(key, "is not a boolean");
    return value->get<bool>();
}

float JsonFields::finiteFloat(const char* key, float fallback) const {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    if (!value->is_number()) fail(key, "is not a number");
    const double number = value->get<double>();
    if (!finiteAsFloat(number)) fail(key, formatNumber(number) + " is not a finite (float) number");
    return static_cast<float>(number);
}

glm::vec2 JsonFields::finiteVec2(const char* key, glm::vec2 fallback) const {
    const nlohmann::json* value = find(key);
    if (!value) return fallback;
    const bool twoFinite = value->is_array() && value->size() == 2 && (*value)[0].is_number() &&
                           (*value)[1].is_number() && finiteAsFloat((*value)[0].get<double>()) &&
                           finiteAsFloat((*value)[1].get<double>());
    if (!twoFinite) fail(key, "is not an array of 2 finite numbers");
    return {static_cast<float>((*value)[0].get<double>()), static_cast<float>((*value)[1].get<double>())};
}

std::optional<std::uint64_t> JsonFields::index(const char* key) const {
    const nlohmann::json* value = find(key);
    if (!value) return std::nullopt;
    if (!value->is_number_unsigned()) fail(key, "is not a non-negative integer");
    return value->get<std::uint64_t>();
}

void JsonFields::warnAboutUnknownKeys(std::initializer_list<const char*> known) const {
    for (const auto& [key, value] : json_->items()) {
        bool isKnown = false;
        for (const char* name : known) isKnown = isKnown || key == name;
        if (!isKnown) warn("unknown property '" + member(key.c_str()) + "' is ignored");
    }
}

} // namespace engine::gltf
