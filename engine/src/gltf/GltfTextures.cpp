#include "GltfTextures.h"

namespace engine::gltf {

namespace {

// The OpenGL enumerants glTF allows for each sampler field.
constexpr int kMagFilters[] = {9728 /*NEAREST*/, 9729 /*LINEAR*/};
constexpr int kMinFilters[] = {9728, 9729, 9984 /*NEAREST_MIPMAP_NEAREST*/, 9985 /*LINEAR_MIPMAP_NEAREST*/,
                               9986 /*NEAREST_MIPMAP_LINEAR*/, 9987 /*LINEAR_MIPMAP_LINEAR*/};
constexpr int kWraps[] = {33071 /*CLAMP_TO_EDGE*/, 33648 /*MIRRORED_REPEAT*/, 10497 /*REPEAT*/};

template <std::size_t N>
std::string listed(const int (&values)[N]) {
    std::string text;
    for (int value : values) text += (text.empty() ? "" : ", ") + std::to_string(value);
    return text;
}

// samplers[i][key] when it is one of `allowed`; `fallback` when absent or -1.
template <std::size_t N>
int enumerant(const nlohmann::json& sampler, const JsonFields& fields, const char* key, const int (&allowed)[N],
              int fallback) {
    const auto value = sampler.find(key);
    if (value == sampler.end()) return fallback;
    if (!value->is_number_integer()) fields.fail(key, "is not an integer");
    const std::int64_t number = value->get<std::int64_t>();
    if (number == -1) return fallback;
    for (int candidate : allowed)
        if (number == candidate) return candidate;
    fields.fail(key, std::to_string(number) + " is not one of " + listed(allowed));
}

constexpr const char* kTransform = "KHR_texture_transform";

UvTransform readTransform(const JsonFields& transform) {
    transform.warnAboutUnknownKeys({"offset", "rotation", "scale", "texCoord", "extensions", "extras"});
    UvTransform result;
    result.offset = transform.finiteVec2("offset", result.offset);
    result.rotation = transform.finiteFloat("rotation", result.rotation);
    result.scale = transform.finiteVec2("scale", result.scale);
    return result;
}

} // namespace

std::vector<Sampler> convertSamplers(const LoadContext& context, const nlohmann::json& document) {
    std::vector<Sampler> samplers;
    const auto list = document.find("samplers");
    if (list == document.end()) return samplers;  // its type is checked by checkPropertyTypes
    for (std::size_t i = 0; i < list->size(); ++i) {
        const nlohmann::json& json = (*list)[i];
        std::string name;
        if (const auto found = json.find("name"); found != json.end() && found->is_string()) name = found->get<std::string>();
        const JsonFields fields(context, indexedNamed("samplers", i, name), json, "");
        Sampler sampler;
        sampler.magFilter = enumerant(json, fields, "magFilter", kMagFilters, sampler.magFilter);
        sampler.minFilter = enumerant(json, fields, "minFilter", kMinFilters, sampler.minFilter);
        sampler.wrapS = enumerant(json, fields, "wrapS", kWraps, sampler.wrapS);
        sampler.wrapT = enumerant(json, fields, "wrapT", kWraps, sampler.wrapT);
        samplers.push_back(sampler);
    }
    return samplers;
}

TextureRef convertTextureRef(const tinygltf::Model& model, const std::vector<Sampler>& samplers, int textureIndex,
                             const JsonFields& fields) {
    TextureRef ref;
    if (textureIndex < 0) return ref;
    const tinygltf::Texture& texture = model.textures[textureIndex];
    ref.image = texture.source;
    if (ref.image < 0) fields.warn(fields.member("index") + ": " + indexed("textures", textureIndex) + " has no image");
    if (texture.sampler >= 0) ref.sampler = samplers.at(texture.sampler);

    std::uint64_t texCoord = fields.index("texCoord").value_or(0);
    std::string texCoordMember = fields.member("texCoord");
    if (const std::optional<JsonFields> transform = fields.extension(kTransform)) {
        ref.transform = readTransform(*transform);
        // The extension's texCoord overrides the textureInfo's (it names the set the
        // transform was authored for).
        if (const std::optional<std::uint64_t> set = transform->index("texCoord")) {
            texCoord = *set;
            texCoordMember = transform->member("texCoord");
        }
    }
    if (texCoord > 1) {
        fields.warn(texCoordMember + " " + std::to_string(texCoord) +
                    " is not drawn (only TEXCOORD_0 and TEXCOORD_1 are read); TEXCOORD_0 is used instead");
        texCoord = 0;
    }
    ref.texCoord = static_cast<int>(texCoord);
    return ref;
}

} // namespace engine::gltf
