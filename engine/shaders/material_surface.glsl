// The material's surface as the lit pass shades it (glTF 2.0 metallic-roughness): each
// property its factor times its texture where the material has one (a define per texture,
// MaterialShading.h, so a material without it pays no fetch). Textures are sampled in
// uniform control flow, before any light's branch (lit.frag).
uniform float uMetallic;
uniform float uRoughness;
uniform vec3 uEmissive;  // emissiveFactor x KHR_materials_emissive_strength
#ifdef METALLIC_ROUGHNESS_TEXTURE
layout(binding = METALLIC_ROUGHNESS_TEXTURE_UNIT) uniform sampler2D uMetallicRoughnessTexture;
#endif
#ifdef NORMAL_TEXTURE
layout(binding = NORMAL_TEXTURE_UNIT) uniform sampler2D uNormalTexture;
uniform float uNormalScale;
in vec3 vEyeTangent;    // lit.vert: the tangent frame in eye space
in vec3 vEyeBitangent;
#endif
#ifdef OCCLUSION_TEXTURE
layout(binding = OCCLUSION_TEXTURE_UNIT) uniform sampler2D uOcclusionTexture;
uniform float uOcclusionStrength;
#endif
#ifdef EMISSIVE_TEXTURE
layout(binding = EMISSIVE_TEXTURE_UNIT) uniform sampler2D uEmissiveTexture;
#endif

// (metallic, roughness): the factors times the texture's blue and green channels.
vec2 materialMetallicRoughness() {
    vec2 metallicRoughness = vec2(uMetallic, uRoughness);
#ifdef METALLIC_ROUGHNESS_TEXTURE
    metallicRoughness *= texture(uMetallicRoughnessTexture, materialIn.metallicRoughnessUv).bg;
#endif
    return metallicRoughness;
}

// The shading normal for the unit interpolated normal N (front side): the normal map's
// tangent-space normal, its x and y scaled by normalTexture.scale, carried to eye space by
// the tangent frame (glTF 2.0, 3.9.3: scaledNormal = normalize((texel * 2 - 1) *
// (scale, scale, 1))).
vec3 materialNormal(vec3 N) {
#ifdef NORMAL_TEXTURE
    vec3 scaled = normalize((texture(uNormalTexture, materialIn.normalUv).rgb * 2.0 - 1.0) *
                            vec3(uNormalScale, uNormalScale, 1.0));
    return normalize(vEyeTangent * scaled.x + vEyeBitangent * scaled.y + N * scaled.z);
#else
    return N;
#endif
}

// The ambient term with the occlusion texture applied: 1 + strength * (red - 1).
vec3 materialOccludedAmbient(vec3 ambient) {
#ifdef OCCLUSION_TEXTURE
    return ambient * (1.0 + uOcclusionStrength * (texture(uOcclusionTexture, materialIn.occlusionUv).r - 1.0));
#else
    return ambient;
#endif
}

// The emitted radiance: the factor times the texture's (sRGB-decoded) color.
vec3 materialEmissive() {
#ifdef EMISSIVE_TEXTURE
    return uEmissive * texture(uEmissiveTexture, materialIn.emissiveUv).rgb;
#else
    return uEmissive;
#endif
}
