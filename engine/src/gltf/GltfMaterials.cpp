// glTF materials (metallic-roughness core) to engine materials.
#include "GltfConvert.h"

#include <cmath>

namespace engine::gltf {

namespace {

class MaterialConverter {
public:
    MaterialConverter(const LoadContext& context, const tinygltf::Model& model, std::size_t index)
        : context_(context), model_(model), source_(model.materials[index]),
          object_(indexedNamed("materials", index, source_.name)) {}

    Material convert() const {
        const tinygltf::PbrMetallicRoughness& pbr = source_.pbrMetallicRoughness;
        Material material;
        material.name = source_.name;
        material.baseColorFactor = glm::vec4(vector<4>("baseColorFactor", pbr.baseColorFactor, glm::dvec4(1.0), 1.0));
        material.baseColorTexture.image = baseColorImage(pbr.baseColorTexture.index);
        material.metallicFactor = static_cast<float>(inRange("metallicFactor", pbr.metallicFactor, 1.0));
        material.roughnessFactor = static_cast<float>(inRange("roughnessFactor", pbr.roughnessFactor, 1.0));
        // No upper bound: KHR_materials_emissive_strength files may exceed 1.
        material.emissiveFactor = glm::vec3(vector<3>("emissiveFactor", source_.emissiveFactor, glm::dvec3(0.0), INFINITY));
        material.doubleSided = source_.doubleSided;
        material.alphaMode = alphaMode();
        material.alphaCutoff = static_cast<float>(inRange("alphaCutoff", source_.alphaCutoff, INFINITY));
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

    int baseColorImage(int texture) const {
        if (texture < 0) return -1;
        const int image = model_.textures[texture].source;
        if (image < 0) context_.warn(object_, "baseColorTexture " + indexed("textures", texture) + " has no image");
        return image;
    }

    AlphaMode alphaMode() const {
        if (source_.alphaMode == "OPAQUE") return AlphaMode::Opaque;
        if (source_.alphaMode == "MASK") return AlphaMode::Mask;
        if (source_.alphaMode == "BLEND") return AlphaMode::Blend;
        context_.fail(object_, "alphaMode '" + source_.alphaMode + "' is not OPAQUE, MASK or BLEND");
    }

    const LoadContext& context_;
    const tinygltf::Model& model_;
    const tinygltf::Material& source_;
    std::string object_;
};

} // namespace

std::vector<Material> convertMaterials(const LoadContext& context, const tinygltf::Model& model) {
    std::vector<Material> materials;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        materials.push_back(MaterialConverter(context, model, i).convert());
    return materials;
}

} // namespace engine::gltf
