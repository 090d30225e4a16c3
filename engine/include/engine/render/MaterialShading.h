#pragma once
// The material parts of every shader that draws scene primitives: the lit pass, the shadow
// plugin's depth passes and the truth's surface capture. One vertex routine (base color UV
// through the material's TEXCOORD_n and KHR_texture_transform, vertex color) and one
// fragment routine (factor x vertex color x texture, alpha test), so the shaded image, the
// shadow casters and the truth cut their holes in the same places.
//
// Each feature is a define, and each combination a scene uses is its own program: llvmpipe
// pays for a texture fetch even in an untaken branch, and for a possible discard in every
// fragment (it defers depth writes past the shading), so an opaque untextured primitive
// gets a program with neither.
#include "engine/render/MaterialTextures.h"
#include "engine/render/SceneGpu.h"

#include <string>

namespace engine {

struct Material;
struct Scene;
namespace gl { class Program; }

// Feature bits of the material parts.
enum MaterialFeature : unsigned {
    kMaterialTexture = 1u << 0,      // sample the base color texture
    kMaterialVertexColor = 1u << 1,  // multiply by COLOR_0
    kMaterialAlphaTest = 1u << 2,    // discard below the cutoff
    // The surface textures, only for MaterialUse::Shading (they change no coverage).
    kMaterialMetallicRoughnessTexture = 1u << 3,
    kMaterialNormalTexture = 1u << 4,  // also needs the primitive's tangents
    kMaterialOcclusionTexture = 1u << 5,
    kMaterialEmissiveTexture = 1u << 6,
};
constexpr unsigned kMaterialFeatureCombinations = 128;
// The feature bit that samples `texture`.
constexpr unsigned materialTextureFeature(MaterialTexture texture) {
    return texture == MaterialTexture::BaseColor ? kMaterialTexture : 1u << (2 + static_cast<unsigned>(texture));
}

enum class MaterialUse {
    // The camera's view, shaded: alpha tested for MASK materials (alphaCutoff); every
    // texture the material has and vertex color wherever the primitive has them.
    Shading,
    // What the camera sees, not how it is shaded (the truth's surface capture): the same
    // coverage as Shading (base color, vertex color, alpha test), no surface textures.
    ViewCoverage,
    // A shadow caster: only what decides coverage matters. Alpha tested where the
    // material's shadowAlphaCutoff says so (MASK, and BLEND's casting policy), at full
    // resolution (level 0) with the sampler's magnification filter, as the truth samples;
    // an opaque caster needs no material part at all.
    ShadowCasting,
};

// The material for a primitive (glTF's default material when it names none).
const Material& materialOf(const Scene& scene, const SceneGpu::Primitive& primitive);

// The features `primitive` needs for `use`.
unsigned materialFeatures(const Scene& scene, const SceneGpu& gpu, const SceneGpu::Primitive& primitive,
                          MaterialUse use);

// GLSL lines to put after "#version": the feature defines, attribute locations and the
// varyings' interface block. Then the stage's source may use materialVertexGlsl() (call
// passMaterialInputs() in main) or materialFragmentGlsl() (materialBaseColor(),
// discardBelowAlphaCutoff(alpha) with kMaterialAlphaTest).
std::string materialDefines(unsigned features, MaterialUse use);
const char* materialVertexGlsl();
const char* materialFragmentGlsl();
// The lit pass's surface (MaterialUse::Shading), after materialFragmentGlsl():
// materialMetallicRoughness(), materialNormal(N), materialOccludedAmbient(ambient),
// materialEmissive().
const char* materialSurfaceGlsl();

// Sets the material uniforms `features` declare on the program in use and binds the
// textures they sample (each with its sampler's state) to their units.
void applyMaterial(const gl::Program& program, const Scene& scene, const SceneGpu& gpu,
                   const SceneGpu::Primitive& primitive, unsigned features, MaterialUse use);

} // namespace engine
