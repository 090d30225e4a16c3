// The material's per-vertex inputs, shared by every pass that draws scene primitives (the
// lit pass, the shadow depth passes, the truth's surface capture): the base color UV (the
// material's TEXCOORD_n set through its KHR_texture_transform) and the vertex color.
// MaterialShading.h prepends the feature defines and attribute locations.
#ifdef MATERIAL_VARYINGS
out MATERIAL_VARYINGS materialOut;
#endif
#ifdef BASE_COLOR_TEXTURE
layout(location = ATTRIB_TEXCOORD0) in vec2 inTexcoord0;
layout(location = ATTRIB_TEXCOORD1) in vec2 inTexcoord1;
uniform int uBaseColorTexCoord;       // 0: TEXCOORD_0, 1: TEXCOORD_1
uniform mat3 uBaseColorUvTransform;   // KHR_texture_transform (identity without one)
#endif
#ifdef VERTEX_COLOR
layout(location = ATTRIB_COLOR) in vec4 inColor;
#endif

// Writes the material varyings; call once from main().
void passMaterialInputs() {
#ifdef BASE_COLOR_TEXTURE
    // Transformed per vertex: the transform is affine, so interpolating its result is
    // interpolating the UVs and transforming each fragment's.
    vec2 uv = uBaseColorTexCoord == 1 ? inTexcoord1 : inTexcoord0;
    materialOut.baseColorUv = (uBaseColorUvTransform * vec3(uv, 1.0)).xy;
#endif
#ifdef VERTEX_COLOR
    materialOut.color = inColor;
#endif
}
