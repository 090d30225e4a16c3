#pragma once
// Small checked readers for JSON settings: every failure names the file and the key path,
// and every key an object may hold is listed so unknown keys are reported, not ignored.
#include "engine/util/Error.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace engine::json {

// Throws if `object` is not an object or has a key not in `allowed`.
void requireKnownKeys(const nlohmann::json& object, std::initializer_list<const char*> allowed,
                      const std::string& file, const std::string& where);
// The same with the keys from a table (e.g. a plugin's list of its settings).
void requireKnownKeys(const nlohmann::json& object, const std::vector<std::string>& allowed,
                      const std::string& file, const std::string& where);

double readNumber(const nlohmann::json& value, const std::string& file, const std::string& where);
bool readBool(const nlohmann::json& value, const std::string& file, const std::string& where);
std::string readString(const nlohmann::json& value, const std::string& file,
                       const std::string& where);
glm::dvec3 readVec3(const nlohmann::json& value, const std::string& file, const std::string& where);

} // namespace engine::json
