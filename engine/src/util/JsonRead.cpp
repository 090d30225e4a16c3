#include "engine/util/JsonRead.h"

#include <cmath>
#include <algorithm>

namespace engine::json {

void requireKnownKeys(const nlohmann::json& object, std::initializer_list<const char*> allowed,
                      const std::string& file, const std::string& where) {
    requireKnownKeys(object, std::vector<std::string>(allowed.begin(), allowed.end()), file, where);
}

void requireKnownKeys(const nlohmann::json& object, const std::vector<std::string>& allowed,
                      const std::string& file, const std::string& where) {
    if (!object.is_object()) throwInputError(file, where, "must be a JSON object");
    for (const auto& item : object.items()) {
        if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
        std::string list;
        for (const std::string& key : allowed) list += (list.empty() ? "" : ", ") + key;
        throwInputError(file, where.empty() ? item.key() : where + "." + item.key(),
                        "unknown key (known: " + list + ")");
    }
}

double readNumber(const nlohmann::json& value, const std::string& file, const std::string& where) {
    if (!value.is_number()) throwInputError(file, where, "must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) throwInputError(file, where, "must be finite");
    return number;
}

bool readBool(const nlohmann::json& value, const std::string& file, const std::string& where) {
    if (!value.is_boolean()) throwInputError(file, where, "must be true or false");
    return value.get<bool>();
}

std::string readString(const nlohmann::json& value, const std::string& file,
                       const std::string& where) {
    if (!value.is_string()) throwInputError(file, where, "must be a string");
    return value.get<std::string>();
}

glm::dvec3 readVec3(const nlohmann::json& value, const std::string& file, const std::string& where) {
    if (!value.is_array() || value.size() != 3)
        throwInputError(file, where, "must be an array of 3 numbers");
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = readNumber(value[i], file, where + "[" + std::to_string(i) + "]");
    return out;
}

} // namespace engine::json
