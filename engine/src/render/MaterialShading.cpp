#include "engine/render/MaterialShading.h"

#include "engine/gl/Program.h"
#include "engine/scene/Scene.h"

namespace engine {

namespace shaders {
extern const char material_vertex_glsl[];
extern const char material_fragment_glsl[];
extern const char material_surface_glsl[];
}

namespace {

// How the shaders name a material texture: its define, the varying its UV is passed in
// and its index in the uTexCoordSet / uUvTransform arrays (its MaterialTexture value).
struct TextureGlsl {
    const char* define;
    const char* uvVarying;
};

TextureGlsl glslOf(MaterialTexture texture) {
    switch (texture) {
    case MaterialTexture::BaseColor: return {"BASE_COLOR_TEXTURE", "baseColorUv"};
    case MaterialTexture::MetallicRoughness: return {"METALLIC_ROUGHNESS_TEXTURE", "metallicRoughnessUv"};
    case MaterialTexture::Normal: return {"NORMAL_TEXTURE", "normalUv"};
    case MaterialTexture::Occlusion: return {"OCCLUSION_TEXTURE", "occlusionUv"};
    case MaterialTexture::Emissive: return {"EMISSIVE_TEXTURE", "emissiveUv"};
    }
    return {"", ""};
}

bool usesSurfaceTextures(MaterialUse use) { return use == MaterialUse::Shading; }

// Whether a material texture of `kind` can be sampled for `primitive` in `use`.
bool samples(const SceneGpu& gpu, const SceneGpu::Primitive& primitive, MaterialTexture kind, MaterialUse use) {
    if (kind != MaterialTexture::BaseColor && !usesSurfaceTextures(use)) return false;
    // A normal map turns the normal in the tangent frame; without one it has no meaning.
    if (kind == MaterialTexture::Normal && !primitive.hasTangents) return false;
    return gpu.materialTexture(primitive.material, kind) != 0;
}

} // namespace

const TextureRef& materialTextureRef(const Material& material, MaterialTexture texture) {
    switch (texture) {
    case MaterialTexture::BaseColor: return material.baseColorTexture;
    case MaterialTexture::MetallicRoughness: return material.metallicRoughnessTexture;
    case MaterialTexture::Normal: return material.normalTexture;
    case MaterialTexture::Occlusion: return material.occlusionTexture;
    case MaterialTexture::Emissive: return material.emissiveTexture;
    }
    return material.baseColorTexture;
}

const Material& materialOf(const Scene& scene, const SceneGpu::Primitive& primitive) {
    static const Material kDefaultMaterial{};
    return primitive.material >= 0 ? scene.materials.at(primitive.material) : kDefaultMaterial;
}

unsigned materialFeatures(const Scene& scene, const SceneGpu& gpu, const SceneGpu::Primitive& primitive,
                          MaterialUse use) {
    const Material& material = materialOf(scene, primitive);
    const bool alphaTest = use == MaterialUse::ShadowCasting ? castsAlphaTested(material)
                                                             : material.alphaMode == AlphaMode::Mask;
    // A caster without an alpha test needs neither color nor texture: its coverage is its
    // geometry.
    if (use == MaterialUse::ShadowCasting && !alphaTest) return 0;
    unsigned features = (primitive.hasColors ? kMaterialVertexColor : 0u) | (alphaTest ? kMaterialAlphaTest : 0u);
    for (const MaterialTexture kind : kMaterialTextures)
        if (samples(gpu, primitive, kind, use)) features |= materialTextureFeature(kind);
    return features;
}

std::string materialDefines(unsigned features, MaterialUse use) {
    std::string defines = "#define ATTRIB_TEXCOORD0 " + std::to_string(kAttribTexcoord) +
                          "\n#define ATTRIB_TEXCOORD1 " + std::to_string(kAttribTexcoord1) +
                          "\n#define ATTRIB_COLOR " + std::to_string(kAttribColor) +
                          "\n#define ATTRIB_TANGENT " + std::to_string(kAttribTangent) +
                          "\n#define MATERIAL_TEXTURE_COUNT " + std::to_string(kMaterialTextureCount) + "\n";
    // Per sampled texture its define and unit, and MATERIAL_TEXTURE_UVS(F) expanding to
    // F(varying, index) for each, as FOR_EACH_LIGHT does for the lights (lit.frag).
    std::string varyings, uvs;
    for (const MaterialTexture kind : kMaterialTextures) {
        if (!(features & materialTextureFeature(kind))) continue;
        const TextureGlsl glsl = glslOf(kind);
        defines += std::string("#define ") + glsl.define + "\n#define " + glsl.define + "_UNIT " +
                   std::to_string(materialTextureUnit(kind)) + "\n";
        varyings += std::string(" vec2 ") + glsl.uvVarying + ";";
        uvs += std::string(" F(") + glsl.uvVarying + ", " + std::to_string(static_cast<unsigned>(kind)) + ")";
    }
    if (!uvs.empty()) defines += "#define MATERIAL_TEXTURE_UVS(F)" + uvs + "\n";
    const bool color = features & kMaterialVertexColor;
    if (color) defines += "#define VERTEX_COLOR\n";
    if (features & kMaterialAlphaTest) defines += "#define ALPHA_TEST\n";
    if (use == MaterialUse::ShadowCasting) defines += "#define CASTER_ALPHA\n";
    // The varyings as one interface block: blocks match between stages by block name, so
    // a geometry stage in between (the truth's capture) can pass them on under its own
    // instance names.
    if (color) varyings += " vec4 color;";
    if (!varyings.empty()) defines += "#define MATERIAL_VARYINGS MaterialVaryings {" + varyings + " }\n";
    return defines;
}

const char* materialVertexGlsl() { return shaders::material_vertex_glsl; }
const char* materialFragmentGlsl() { return shaders::material_fragment_glsl; }
const char* materialSurfaceGlsl() { return shaders::material_surface_glsl; }

void applyMaterial(const gl::Program& program, const Scene& scene, const SceneGpu& gpu,
                   const SceneGpu::Primitive& primitive, unsigned features, MaterialUse use) {
    const Material& material = materialOf(scene, primitive);
    if (use != MaterialUse::ShadowCasting || features != 0) program.set("uBaseColorFactor", material.baseColorFactor);
    if (features & kMaterialAlphaTest)
        program.set("uAlphaCutoff", use == MaterialUse::ShadowCasting ? shadowAlphaCutoff(material) : material.alphaCutoff);
    if (use == MaterialUse::Shading) {
        program.set("uMetallic", material.metallicFactor);
        program.set("uRoughness", material.roughnessFactor);
        program.set("uEmissive", material.emissiveFactor);
        if (features & kMaterialNormalTexture) program.set("uNormalScale", material.normalScale);
        if (features & kMaterialOcclusionTexture) program.set("uOcclusionStrength", material.occlusionStrength);
    }
    bool samplesAny = false;
    for (const MaterialTexture kind : kMaterialTextures) {
        if (!(features & materialTextureFeature(kind))) continue;
        samplesAny = true;
        const TextureRef& reference = materialTextureRef(material, kind);
        const std::string index = "[" + std::to_string(static_cast<unsigned>(kind)) + "]";
        program.set("uTexCoordSet" + index, reference.texCoord);
        program.set("uUvTransform" + index, reference.transform.matrix());
        glBindTextureUnit(materialTextureUnit(kind), gpu.materialTexture(primitive.material, kind));
    }
    if (samplesAny) {
        // A UV set the primitive lacks reads (0, 0). Set only where a program reads it: a
        // constant attribute changed before every draw costs llvmpipe's vertex-state
        // validation each time (+0.8 % on the showcase's unshadowed frame, five alternating runs).
        if (!primitive.hasTexcoords) glVertexAttrib2f(kAttribTexcoord, 0.0f, 0.0f);
        if (!primitive.hasTexcoords1) glVertexAttrib2f(kAttribTexcoord1, 0.0f, 0.0f);
    }
}

} // namespace engine
