#pragma once
// TextureAlpha: the base color alpha of a material at a point of a triangle, on the CPU, for
// the ray-traced truth's alpha-tested casters. The sampling rule is the one the depth
// passes use (MaterialShading.h, MaterialUse::ShadowCasting): the full-resolution image
// (level 0), the sampler's magnification filter (NEAREST: one texel; LINEAR: bilinear
// between the four nearest texel centres) and wrap modes, as OpenGL defines them; the UVs
// are the material's TEXCOORD_n through its KHR_texture_transform, interpolated
// barycentrically; times the factor's alpha and the vertex color's alpha.
#include "engine/scene/Scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace truth {

// Alpha of `image` at `uv` (row 0 = v 0 = top, as glTF and the engine's images have it).
double sampleAlpha(const engine::Image& image, const engine::Sampler& sampler, glm::dvec2 uv);

// A primitive's coverage data, ready for per-hit queries.
class AlphaTestedPrimitive {
public:
    // `image` may be null (no texture: the alpha comes from factor and vertex colors).
    AlphaTestedPrimitive(const engine::Primitive& primitive, const engine::Material& material,
                         const engine::Image* image);

    // Alpha at barycentric (u, v) of triangle `triangle` (point = (1-u-v) p0 + u p1 + v p2).
    double alphaAt(unsigned triangle, double u, double v) const;
    // The cutoff below which this caster lets light through (shadowAlphaCutoff).
    double cutoff() const { return cutoff_; }

private:
    const engine::Image* image_;
    engine::Sampler sampler_;
    std::vector<std::uint32_t> indices_;
    std::vector<glm::dvec2> uvs_;    // per vertex, transformed; empty without a texture
    std::vector<double> alphas_;     // per vertex: factor alpha x vertex color alpha
    double cutoff_;
};

} // namespace truth
