// glTF materials (metallic-roughness core; the base color, metallic-roughness, normal,
// occlusion and emissive textures, each with its sampler, UV set and KHR_texture_transform;
// KHR_materials_emissive_strength; our shadow extras) to engine materials.
#include "GltfConvert.h"
#include "GltfJsonFields.h"
#include "GltfTextures.h"

#include <cmath>
#include <optional>

namespace engine::gltf {

namespace {

class MaterialConverter {
public:
    MaterialConverter(const LoadContext& context, const tinygltf::Model& model, const nlohmann::json& document,
                      const std::vector<Sampler>& samplers, std::size_t index)
        : context_(context), model_(model), samplers_(samplers), source_(model.materials[index]),
          object_(indexedNamed("materials", index, source_.name)),
          json_(context, object_, arrayElement(document, "materials", index), "") {}

    Material convert() const {
        const tinygltf::PbrMetallicRoughness& pbr = source_.pbrMetallicRoughness;
        const JsonFields pbrJson = json_.child("pbrMetallicRoughness");
        Material material;
        material.name = source_.name;
        material.baseColorFactor = glm::vec4(vector<4>("baseColorFactor", pbr.baseColorFactor, glm::dvec4(1.0), 1.0));
        material.baseColorTexture = convertTextureRef(model_, samplers_, pbr.baseColorTexture.index,
                                                      pbrJson.child("baseColorTexture"));
        material.metallicFactor = static_cast<float>(inRange("metallicFactor", pbr.metallicFactor, 1.0));
        material.roughnessFactor = static_cast<float>(inRange("roughnessFactor", pbr.roughnessFactor, 1.0));
        material.metallicRoughnessTexture = convertTextureRef(model_, samplers_, pbr.metallicRoughnessTexture.index,
                                                              pbrJson.child("metallicRoughnessTexture"));
        readNormalTexture(material);
        readOcclusionTexture(material);
        // No upper bound: KHR_materials_emissive_strength files may exceed 1.
        material.emissiveFactor = glm::vec3(vector<3>("emissiveFactor", source_.emissiveFactor, glm::dvec3(0.0), INFINITY)) *
                                  emissiveStrength();
        material.emissiveTexture =
            convertTextureRef(model_, samplers_, source_.emissiveTexture.index, json_.child("emissiveTexture"));
        material.doubleSided = source_.doubleSided;
        material.alphaMode = alphaMode();
        material.alphaCutoff = static_cast<float>(inRange("alphaCutoff", source_.alphaCutoff, INFINITY));
        readBlendShadowCutoff(material);
        return material;
    }

private:
    // A number in [0, maximum].
    double inRange(const std::string& what, double value, double maximum) const {
        if (!std::isfinite(value) || value < 0.0 || value > maximum)
            context_.fail(object_, what + " " + formatNumber(value) + " is not a finite number in [0, " +
                                       (std::isinf(maximum) ? std::string("inf") : formatNumber(maximum)) + "]");
        return value;
    }

    // tinygltf leaves a factor's vector empty when the file omits it.
    template <glm::length_t N>
    glm::vec<N, double> vector(const char* what, const std::vector<double>& values, glm::vec<N, double> fallback,
                               double maximum) const {
        if (values.empty()) return fallback;
        if (values.size() != N)
            context_.fail(object_, std::string(what) + " has " + std::to_string(values.size()) + " numbers, not " +
                                       std::to_string(N));
        glm::vec<N, double> result;
        for (glm::length_t c = 0; c < N; ++c)
            result[c] = inRange(std::string(what) + "[" + std::to_string(c) + "]", values[c], maximum);
        return result;
    }

    // normalTexture.scale multiplies the sampled normal's x and y. Any finite number: a
    // negative one turns the relief inside out (a map baked with the other green convention).
    void readNormalTexture(Material& material) const {
        const JsonFields info = json_.child("normalTexture");
        material.normalTexture = convertTextureRef(model_, samplers_, source_.normalTexture.index, info);
        material.normalScale = info.finiteFloat("scale", material.normalScale);
    }

    // occlusionTexture.strength: how much of the occlusion applies, in [0, 1] (glTF 2.0).
    void readOcclusionTexture(Material& material) const {
        const JsonFields info = json_.child("occlusionTexture");
        material.occlusionTexture = convertTextureRef(model_, samplers_, source_.occlusionTexture.index, info);
        const float strength = info.finiteFloat("strength", material.occlusionStrength);
        if (strength < 0.0f || strength > 1.0f) info.fail("strength", formatNumber(strength) + " is not in [0, 1]");
        material.occlusionStrength = strength;
    }

    // KHR_materials_emissive_strength: a factor on the emissive color that may exceed 1.
    // The emitted color is factor x strength x the emissive texture's color (white when
    // absent): the strength folds into the factor, and the lit pass needs only the product.
    float emissiveStrength() const {
        const std::optional<JsonFields> extension = json_.extension("KHR_materials_emissive_strength");
        if (!extension) return 1.0f;
        extension->warnAboutUnknownKeys({"emissiveStrength", "extensions", "extras"});
        const float strength = extension->finiteFloat("emissiveStrength", 1.0f);
        if (strength < 0.0f) extension->fail("emissiveStrength", formatNumber(strength) + " is not >= 0");
        return strength;
    }

    AlphaMode alphaMode() const {
        if (source_.alphaMode == "OPAQUE") return AlphaMode::Opaque;
        if (source_.alphaMode == "MASK") return AlphaMode::Mask;
        if (source_.alphaMode == "BLEND") return AlphaMode::Blend;
        context_.fail(object_, "alphaMode '" + source_.alphaMode + "' is not OPAQUE, MASK or BLEND");
    }

    // extras.shadow_alpha_cutoff: where a BLEND caster's alpha stops the light. The other
    // modes have their answer already, so the key there is a mistake worth reporting. The
    // rest of extras belongs to others (extras that are not an object hold no such key).
    void readBlendShadowCutoff(Material& material) const {
        const nlohmann::json* extras = json_.find("extras");
        if (!extras || !extras->is_object() || !extras->contains("shadow_alpha_cutoff")) return;
        const JsonFields fields(context_, object_, *extras, "extras");
        const float cutoff = fields.finiteFloat("shadow_alpha_cutoff", material.blendShadowCutoff);
        if (cutoff < 0.0f) fields.fail("shadow_alpha_cutoff", formatNumber(cutoff) + " is not >= 0");
        if (material.alphaMode == AlphaMode::Mask)
            fields.fail("shadow_alpha_cutoff", "is only for alphaMode BLEND (a MASK material casts by its alphaCutoff)");
        if (material.alphaMode == AlphaMode::Opaque)
            fields.fail("shadow_alpha_cutoff", "is only for alphaMode BLEND (an OPAQUE material casts solid)");
        material.blendShadowCutoff = cutoff;
    }

    const LoadContext& context_;
    const tinygltf::Model& model_;
    const std::vector<Sampler>& samplers_;
    const tinygltf::Material& source_;
    std::string object_;
    JsonFields json_;
};

} // namespace

std::vector<Material> convertMaterials(const LoadContext& context, const tinygltf::Model& model,
                                       const nlohmann::json& document) {
    const std::vector<Sampler> samplers = convertSamplers(context, document);
    std::vector<Material> materials;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        materials.push_back(MaterialConverter(context, model, document, samplers, i).convert());
    return materials;
}

} // namespace engine::gltf
