#include "engine/render/MaterialShading.h"

#include "engine/gl/Program.h"
#include "engine/scene/Scene.h"

namespace engine {

namespace shaders {
extern const char material_vertex_glsl[];
extern const char material_fragment_glsl[];
}

const Material& materialOf(const Scene& scene, const SceneGpu::Primitive& primitive) {
    static const Material kDefaultMaterial{};
    return primitive.material >= 0 ? scene.materials.at(primitive.material) : kDefaultMaterial;
}

unsigned materialFeatures(const Scene& scene, const SceneGpu& gpu, const SceneGpu::Primitive& primitive,
                          MaterialUse use) {
    const Material& material = materialOf(scene, primitive);
    const bool alphaTest = use == MaterialUse::Shading ? material.alphaMode == AlphaMode::Mask
                                                       : castsAlphaTested(material);
    // A caster without an alpha test needs neither color nor texture: its coverage is its
    // geometry.
    if (use == MaterialUse::ShadowCasting && !alphaTest) return 0;
    return (gpu.baseColorTexture(primitive.material) != 0 ? kMaterialTexture : 0u) |
           (primitive.hasColors ? kMaterialVertexColor : 0u) | (alphaTest ? kMaterialAlphaTest : 0u);
}

std::string materialDefines(unsigned features, MaterialUse use) {
    const bool texture = features & kMaterialTexture, color = features & kMaterialVertexColor;
    std::string defines = "#define ATTRIB_TEXCOORD0 " + std::to_string(kAttribTexcoord) +
                          "\n#define ATTRIB_TEXCOORD1 " + std::to_string(kAttribTexcoord1) +
                          "\n#define ATTRIB_COLOR " + std::to_string(kAttribColor) +
                          "\n#define MATERIAL_TEXTURE_UNIT " + std::to_string(kMaterialTextureUnit) + "\n";
    if (texture) defines += "#define BASE_COLOR_TEXTURE\n";
    if (color) defines += "#define VERTEX_COLOR\n";
    if (features & kMaterialAlphaTest) defines += "#define ALPHA_TEST\n";
    if (use == MaterialUse::ShadowCasting) defines += "#define CASTER_ALPHA\n";
    // The varyings as one interface block: blocks match between stages by block name, so
    // a geometry stage in between (the truth's capture) can pass them on under its own
    // instance names.
    if (texture || color)
        defines += std::string("#define MATERIAL_VARYINGS MaterialVaryings {") +
                   (texture ? " vec2 baseColorUv;" : "") + (color ? " vec4 color;" : "") + " }\n";
    return defines;
}

const char* materialVertexGlsl() { return shaders::material_vertex_glsl; }
const char* materialFragmentGlsl() { return shaders::material_fragment_glsl; }

void applyMaterial(const gl::Program& program, const Scene& scene, const SceneGpu& gpu,
                   const SceneGpu::Primitive& primitive, unsigned features, MaterialUse use) {
    const Material& material = materialOf(scene, primitive);
    if (use == MaterialUse::Shading || features != 0) program.set("uBaseColorFactor", material.baseColorFactor);
    if (features & kMaterialAlphaTest)
        program.set("uAlphaCutoff", use == MaterialUse::Shading ? material.alphaCutoff : shadowAlphaCutoff(material));
    if (features & kMaterialTexture) {
        // A UV set the primitive lacks reads (0, 0). Set only where a program reads it: a
        // constant attribute changed before every draw costs llvmpipe's vertex-state
        // validation each time (+0.8 % on the showcase's unshadowed frame, five alternating runs).
        if (!primitive.hasTexcoords) glVertexAttrib2f(kAttribTexcoord, 0.0f, 0.0f);
        if (!primitive.hasTexcoords1) glVertexAttrib2f(kAttribTexcoord1, 0.0f, 0.0f);
        program.set("uBaseColorTexCoord", material.baseColorTexture.texCoord);
        program.set("uBaseColorUvTransform", material.baseColorTexture.transform.matrix());
        glBindTextureUnit(kMaterialTextureUnit, gpu.baseColorTexture(primitive.material));
    }
}

} // namespace engine
