#include "GltfPropertyTypes.h"

#include <string_view>
#include <utility>
#include <vector>

namespace engine::gltf {

namespace {

enum class Kind { Object, Array, String, Boolean, Number, Index, NumberArray, IndexArray };

// A property path ('/'-separated; '*' is every element of an array or every member of an
// object) and the type its value must have when present. Parents come before children.
struct Rule {
    std::string_view path;
    Kind kind;
};

constexpr Rule kRules[] = {
    {"scene", Kind::Index},
    {"scenes", Kind::Array}, {"scenes/*", Kind::Object}, {"scenes/*/nodes", Kind::IndexArray},
    {"scenes/*/name", Kind::String},
    {"nodes", Kind::Array}, {"nodes/*", Kind::Object}, {"nodes/*/name", Kind::String},
    {"nodes/*/children", Kind::IndexArray}, {"nodes/*/mesh", Kind::Index}, {"nodes/*/camera", Kind::Index},
    {"nodes/*/skin", Kind::Index}, {"nodes/*/matrix", Kind::NumberArray},
    {"nodes/*/translation", Kind::NumberArray}, {"nodes/*/rotation", Kind::NumberArray},
    {"nodes/*/scale", Kind::NumberArray}, {"nodes/*/extensions", Kind::Object},
    {"meshes", Kind::Array}, {"meshes/*", Kind::Object}, {"meshes/*/name", Kind::String},
    {"meshes/*/primitives", Kind::Array}, {"meshes/*/primitives/*", Kind::Object},
    {"meshes/*/primitives/*/attributes", Kind::Object}, {"meshes/*/primitives/*/attributes/*", Kind::Index},
    {"meshes/*/primitives/*/indices", Kind::Index}, {"meshes/*/primitives/*/material", Kind::Index},
    {"meshes/*/primitives/*/mode", Kind::Index},
    {"meshes/*/primitives/*/targets", Kind::Array}, {"meshes/*/primitives/*/targets/*", Kind::Object},
    {"meshes/*/primitives/*/targets/*/*", Kind::Index}, {"meshes/*/weights", Kind::NumberArray},
    {"nodes/*/weights", Kind::NumberArray},
    {"skins", Kind::Array}, {"skins/*", Kind::Object}, {"skins/*/joints", Kind::IndexArray},
    {"skins/*/inverseBindMatrices", Kind::Index}, {"skins/*/skeleton", Kind::Index}, {"skins/*/name", Kind::String},
    {"accessors", Kind::Array}, {"accessors/*", Kind::Object}, {"accessors/*/bufferView", Kind::Index},
    {"accessors/*/byteOffset", Kind::Index}, {"accessors/*/componentType", Kind::Index},
    {"accessors/*/normalized", Kind::Boolean}, {"accessors/*/count", Kind::Index},
    {"accessors/*/type", Kind::String}, {"accessors/*/sparse", Kind::Object},
    {"bufferViews", Kind::Array}, {"bufferViews/*", Kind::Object}, {"bufferViews/*/buffer", Kind::Index},
    {"bufferViews/*/byteOffset", Kind::Index}, {"bufferViews/*/byteLength", Kind::Index},
    {"bufferViews/*/byteStride", Kind::Index},
    {"buffers", Kind::Array}, {"buffers/*", Kind::Object}, {"buffers/*/byteLength", Kind::Index},
    {"buffers/*/uri", Kind::String},
    {"images", Kind::Array}, {"images/*", Kind::Object}, {"images/*/uri", Kind::String},
    {"images/*/bufferView", Kind::Index}, {"images/*/mimeType", Kind::String}, {"images/*/name", Kind::String},
    {"textures", Kind::Array}, {"textures/*", Kind::Object}, {"textures/*/source", Kind::Index},
    {"textures/*/sampler", Kind::Index}, {"samplers", Kind::Array}, {"samplers/*", Kind::Object},
    {"materials", Kind::Array}, {"materials/*", Kind::Object}, {"materials/*/name", Kind::String},
    {"materials/*/pbrMetallicRoughness", Kind::Object},
    {"materials/*/pbrMetallicRoughness/baseColorFactor", Kind::NumberArray},
    {"materials/*/pbrMetallicRoughness/baseColorTexture", Kind::Object},
    {"materials/*/pbrMetallicRoughness/baseColorTexture/index", Kind::Index},
    {"materials/*/pbrMetallicRoughness/baseColorTexture/texCoord", Kind::Index},
    {"materials/*/pbrMetallicRoughness/metallicFactor", Kind::Number},
    {"materials/*/pbrMetallicRoughness/roughnessFactor", Kind::Number},
    {"materials/*/pbrMetallicRoughness/metallicRoughnessTexture", Kind::Object},
    {"materials/*/pbrMetallicRoughness/metallicRoughnessTexture/index", Kind::Index},
    {"materials/*/normalTexture", Kind::Object}, {"materials/*/normalTexture/index", Kind::Index},
    {"materials/*/occlusionTexture", Kind::Object}, {"materials/*/occlusionTexture/index", Kind::Index},
    {"materials/*/emissiveTexture", Kind::Object}, {"materials/*/emissiveTexture/index", Kind::Index},
    {"materials/*/emissiveFactor", Kind::NumberArray}, {"materials/*/alphaMode", Kind::String},
    {"materials/*/alphaCutoff", Kind::Number}, {"materials/*/doubleSided", Kind::Boolean},
    {"cameras", Kind::Array}, {"cameras/*", Kind::Object}, {"cameras/*/type", Kind::String},
    {"cameras/*/name", Kind::String}, {"cameras/*/perspective", Kind::Object},
    {"cameras/*/perspective/yfov", Kind::Number}, {"cameras/*/perspective/znear", Kind::Number},
    {"cameras/*/perspective/zfar", Kind::Number}, {"cameras/*/perspective/aspectRatio", Kind::Number},
    {"cameras/*/orthographic", Kind::Object}, {"cameras/*/orthographic/xmag", Kind::Number},
    {"cameras/*/orthographic/ymag", Kind::Number}, {"cameras/*/orthographic/znear", Kind::Number},
    {"cameras/*/orthographic/zfar", Kind::Number},
    {"animations", Kind::Array}, {"animations/*", Kind::Object}, {"animations/*/name", Kind::String},
    {"animations/*/channels", Kind::Array}, {"animations/*/channels/*", Kind::Object},
    {"animations/*/channels/*/sampler", Kind::Index}, {"animations/*/channels/*/target", Kind::Object},
    {"animations/*/channels/*/target/node", Kind::Index}, {"animations/*/channels/*/target/path", Kind::String},
    {"animations/*/samplers", Kind::Array}, {"animations/*/samplers/*", Kind::Object},
    {"animations/*/samplers/*/input", Kind::Index}, {"animations/*/samplers/*/output", Kind::Index},
    {"animations/*/samplers/*/interpolation", Kind::String},
};

bool isIndex(const nlohmann::json& value) { return value.is_number_unsigned(); }

bool allOf(const nlohmann::json& value, bool (*test)(const nlohmann::json&)) {
    if (!value.is_array()) return false;
    for (const auto& element : value)
        if (!test(element)) return false;
    return true;
}

// The reason `value` is not of `kind`, or nullptr.
const char* mismatch(const nlohmann::json& value, Kind kind) {
    switch (kind) {
    case Kind::Object: return value.is_object() ? nullptr : "is not an object";
    case Kind::Array: return value.is_array() ? nullptr : "is not an array";
    case Kind::String: return value.is_string() ? nullptr : "is not a string";
    case Kind::Boolean: return value.is_boolean() ? nullptr : "is not a boolean";
    case Kind::Number: return value.is_number() ? nullptr : "is not a number";
    case Kind::Index: return isIndex(value) ? nullptr : "is not a non-negative integer";
    case Kind::NumberArray:
        return allOf(value, [](const nlohmann::json& v) { return v.is_number(); }) ? nullptr
                                                                                   : "is not an array of numbers";
    case Kind::IndexArray:
        return allOf(value, isIndex) ? nullptr : "is not an array of non-negative integers";
    }
    return nullptr;
}

struct Located {
    const nlohmann::json* value;
    std::string name;  // "meshes[0].primitives", for messages
};

// Every value the rule's path reaches in the document.
std::vector<Located> resolve(const nlohmann::json& document, std::string_view path) {
    std::vector<Located> current{{&document, ""}};
    while (!path.empty()) {
        const std::size_t slash = path.find('/');
        const std::string_view segment = path.substr(0, slash);
        path = slash == std::string_view::npos ? std::string_view() : path.substr(slash + 1);
        std::vector<Located> next;
        for (const Located& at : current) {
            if (segment == "*" && at.value->is_array()) {
                for (std::size_t i = 0; i < at.value->size(); ++i)
                    next.push_back({&(*at.value)[i], at.name + "[" + std::to_string(i) + "]"});
            } else if (segment == "*" && at.value->is_object()) {
                for (const auto& [key, member] : at.value->items()) next.push_back({&member, at.name + "." + key});
            } else if (segment != "*" && at.value->is_object()) {
                const auto member = at.value->find(std::string(segment));
                if (member != at.value->end())
                    next.push_back({&*member, at.name.empty() ? std::string(segment) : at.name + "." + std::string(segment)});
            }
        }
        current = std::move(next);
    }
    return current;
}

} // namespace

void checkPropertyTypes(const LoadContext& context, const nlohmann::json& document) {
    for (const Rule& rule : kRules)
        for (const Located& located : resolve(document, rule.path))
            if (const char* reason = mismatch(*located.value, rule.kind)) context.fail(located.name, reason);
}

} // namespace engine::gltf
