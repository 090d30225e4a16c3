// The material's per-vertex inputs, shared by every pass that draws scene primitives (the
// lit pass, the shadow depth passes, the truth's surface capture): each sampled texture's
// UV (the material's TEXCOORD_n set for it through its KHR_texture_transform) and the
// vertex color. MaterialShading.h prepends the feature defines, attribute locations and
// MATERIAL_TEXTURE_UVS(F), which expands to F(varying, index) for each sampled texture.
#ifdef MATERIAL_VARYINGS
out MATERIAL_VARYINGS materialOut;
#endif
#ifdef MATERIAL_TEXTURE_UVS
layout(location = ATTRIB_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTRIB_TEXCOORD1) in vec2 inTexcoord1;
// By MaterialTexture: its UV set (0: TEXCOORD_0, 1: TEXCOORD_1) and KHR_texture_transform
// (identity without one).
uniform int uTexCoordSet[MATERIAL_TEXTURE_COUNT];
uniform mat3 uUvTransform[MATERIAL_TEXTURE_COUNT];

// Transformed per vertex: the transform is affine, so interpolating its result is
// interpolating the UVs and transforming each fragment's.
vec2 materialUv(int index) {
    vec2 uv = uTexCoordSet[index] == 1 ? inTexcoord1 : inTexcoord0;
    return (uUvTransform[index] * vec3(uv, 1.0)).xy;
}
#endif
#ifdef VERTEX_COLOR
layout(location = ATTRIB_COLOR) in vec4 inColor;
#endif

// Writes the material varyings; call once from main().
void passMaterialInputs() {
#ifdef MATERIAL_TEXTURE_UVS
#define PASS_UV(varying, index) materialOut.varying = materialUv(index);
    MATERIAL_TEXTURE_UVS(PASS_UV)
#endif
#ifdef VERTEX_COLOR
    materialOut.color = inColor;
#endif
}
