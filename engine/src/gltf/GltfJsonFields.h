#pragma once
// Typed reads of the JSON members tinygltf 2.7.0 does not keep faithfully: it drops an
// extension whose value is not an object (KHR_texture_transform: "Not an object" would
// vanish) and turns a wrongly typed or out-of-int-range number into a default. Extensions
// and extras the loader consumes are therefore read from our own parse, exactly typed.
#include "GltfContext.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace engine::gltf {

// parent[array][index], or a null value when there is no such element (the converters walk
// tinygltf's arrays, which mirror our parse; null reads as "nothing written").
const nlohmann::json& arrayElement(const nlohmann::json& parent, const char* array, std::size_t index);

// The members of one JSON object, read for `object` (e.g. "materials[0] 'leaf'"); each
// message names the member by its path below the object: `path` + "." + key.
class JsonFields {
public:
    // A null `json` is an empty object (nothing written); any other non-object fails.
    JsonFields(const LoadContext& context, std::string object, const nlohmann::json& json, std::string path);

    // The member `key` as fields of its own (empty when absent); fails when it is not an
    // object.
    JsonFields child(const char* key) const;
    // owner.extensions.<name> as fields, or nothing when absent; fails when "extensions"
    // or the extension's value is not an object.
    std::optional<JsonFields> extension(const char* name) const;

    bool has(const char* key) const { return json_->contains(key); }
    const nlohmann::json* find(const char* key) const;
    bool boolean(const char* key, bool fallback) const;
    // A number that stays finite as float (1e39 does not), or `fallback` when absent.
    float finiteFloat(const char* key, float fallback) const;
    // An array of 2 such numbers.
    glm::vec2 finiteVec2(const char* key, glm::vec2 fallback) const;
    // A non-negative integer, or nothing when absent.
    std::optional<std::uint64_t> index(const char* key) const;

    // Warns once per member not in `known` (extension objects may grow; a typo should not
    // pass unnoticed).
    void warnAboutUnknownKeys(std::initializer_list<const char*> known) const;

    // "pbrMetallicRoughness.baseColorTexture.texCoord": how messages name a member.
    std::string member(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
    [[noreturn]] void fail(const char* key, const std::string& reason) const { context_->fail(object_, member(key) + " " + reason); }
    void warn(const std::string& message) const { context_->warn(object_, message); }

private:
    const LoadContext* context_;
    std::string object_;
    const nlohmann::json* json_;
    std::string path_;
};

} // namespace engine::gltf
