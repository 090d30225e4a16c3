// The vertex part of the shadow plugin's visibility hook (engine/render/Frame.h):
// eye-linear texgen per vertex, where fixed-function GL evaluated it.
//   2D maps: (s,t,r,q) = Ee * x_e with the eye planes Ee = S * P_light * L^-1 * V composed
//     in double on the CPU (EYE_LINEAR texgen with world-space planes specified under
//     modelview V^-1, see math/Texgen.h);
//   cube maps: x_world - light = R_V * (x_e - light_e), R_V the rotation of V.
// Both are linear in the eye-space position, so the rasterizer's perspective-correct
// interpolation gives each fragment the value at its own eye position (up to float
// rounding): four interpolated components per light instead of a mat4 product per pixel.
// The plugin generates, after this file, one output per shadowed light and lightTexgen()
// setting them with constant slots.
// Ee, the light's eye-space position and R_V come from shadow_data.glsl's block, placed
// before this file.

vec4 shadowCoord(int slot, vec3 eyePosition) {
    return shadowData.eyePlanes[slot] * vec4(eyePosition, 1.0);
}

vec3 shadowToPoint(int slot, vec3 eyePosition) {
    return mat3(shadowData.eyeToWorld) * (eyePosition - shadowData.lightInEye[slot].xyz);
}
