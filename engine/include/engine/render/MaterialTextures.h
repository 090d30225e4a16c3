#pragma once
// The textures a glTF metallic-roughness material may sample, and where each lives: its
// texture unit, whether its texels are sRGB-encoded colors, and the material's reference.
namespace engine {

struct Material;
struct TextureRef;

enum class MaterialTexture : unsigned { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive };
constexpr unsigned kMaterialTextureCount = 5;
constexpr MaterialTexture kMaterialTextures[kMaterialTextureCount] = {
    MaterialTexture::BaseColor, MaterialTexture::MetallicRoughness, MaterialTexture::Normal,
    MaterialTexture::Occlusion, MaterialTexture::Emissive};

// Each material texture has a texture unit of its own, the first ones of the engine's
// (below kFirstPluginTextureUnit, Frame.h).
constexpr unsigned materialTextureUnit(MaterialTexture texture) { return static_cast<unsigned>(texture); }
constexpr unsigned kMaterialTextureUnit = materialTextureUnit(MaterialTexture::BaseColor);

// Base color and emissive hold colors, encoded in sRGB as glTF requires (GL decodes them
// to linear when sampling); the others hold linear data (metalness, roughness, normals,
// occlusion).
constexpr bool isSrgb(MaterialTexture texture) {
    return texture == MaterialTexture::BaseColor || texture == MaterialTexture::Emissive;
}

// The material's reference to that texture (Material::baseColorTexture, ...).
const TextureRef& materialTextureRef(const Material& material, MaterialTexture texture);

} // namespace engine
