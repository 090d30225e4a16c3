// The material's base color and alpha test, shared by every pass that draws scene
// primitives, so the shaded image, the shadow casters and the truth's surface capture all
// cut the same holes. MaterialShading.h prepends the feature defines. (How the lit pass
// shades the surface is material_surface.glsl.)
uniform vec4 uBaseColorFactor;
#ifdef BASE_COLOR_TEXTURE
layout(binding = BASE_COLOR_TEXTURE_UNIT) uniform sampler2D uBaseColorTexture;
#endif
#ifdef MATERIAL_VARYINGS
in MATERIAL_VARYINGS materialIn;
#endif

// factor x vertex color x texture, in linear values (the texture is sRGB-decoded by GL;
// its alpha is linear either way).
vec4 materialBaseColor() {
    vec4 color = uBaseColorFactor;
#ifdef VERTEX_COLOR
    color *= materialIn.color;
#endif
#ifdef BASE_COLOR_TEXTURE
#ifdef CASTER_ALPHA
    // Shadow casters sample the full-resolution image with the sampler's magnification
    // filter, as the ray-traced truth does: a coarser mip level would widen or close the
    // holes of a fence seen edge-on from the light.
    color *= textureLod(uBaseColorTexture, materialIn.baseColorUv, 0.0);
#else
    color *= texture(uBaseColorTexture, materialIn.baseColorUv);
#endif
#endif
    return color;
}

#ifdef ALPHA_TEST
uniform float uAlphaCutoff;
// Only programs with ALPHA_TEST can discard: in a shader that can, llvmpipe defers depth
// writes past the shading, so opaque materials keep programs without it.
void discardBelowAlphaCutoff(float alpha) {
    if (alpha < uAlphaCutoff) discard;
}
#endif
