// The shadow plugin's per-light visibility hook, inserted into the engine's lit fragment
// shader (see engine/render/Frame.h). It returns (shade, dimming) for a light:
//   2D maps (spot, directional): (s,t,r,q) = Ee * x_e with the eye planes
//     Ee = S * P_light * L^-1 * V composed in double on the CPU (EYE_LINEAR texgen with
//     world-space planes specified under modelview V^-1), and the hardware comparison
//     r/q <= map(s/q, t/q) through a sampler2DShadow (GL_LINEAR = 2x2 PCF);
//   cube maps (point): the major-axis depth of (x_world - light) against a samplerCubeShadow.
// Points the map cannot speak for are decided here, explicitly, never by clamping:
//   q <= 0 (behind the light): never lit, no back-projection;
//   outside the map laterally: unlit for spot lights (outside the cone), lit for
//   directional lights (their frustum is fitted to every receiver the camera sees);
//   nearer than the near plane: lit (near is fitted to the nearest caster);
//   beyond the far plane: compared at r = 1, i.e. behind everything the map holds.
#define SHADOW_NONE 0
#define SHADOW_2D 1
#define SHADOW_CUBE 2

// x: kind, y: sampler index, z: dimming, w: the shade outside the map (2D maps) or of
// every point (SHADOW_NONE: 1 for lights without shadows, 0 for a spot light whose
// frustum holds nothing the camera sees, i.e. every visible point is outside its cone).
uniform vec4 uShadowParams[MAX_LIGHTS];
uniform mat4 uShadowEyePlanes[MAX_LIGHTS];   // Ee, rows s,t,r,q (2D maps)
uniform vec4 uShadowPointLight[MAX_LIGHTS];  // eye-space light position, near (cube maps)
uniform float uShadowPointFar[MAX_LIGHTS];   // far (cube maps)
uniform mat3 uShadowEyeToWorld;              // rotation of V: cube lookups use world axes
layout(binding = SHADOW_FIRST_UNIT) uniform sampler2DShadow uShadowMaps2D[MAX_SHADOW_2D];
layout(binding = SHADOW_FIRST_UNIT + MAX_SHADOW_2D) uniform samplerCubeShadow
    uShadowMapsCube[MAX_SHADOW_CUBE];

// Sampler arrays are indexed with constants only: llvmpipe (Mesa 22.3) crashes in LLVM
// compiling a dynamically indexed sampler array inside the lit pass's light loop.
float compare2D(int index, vec3 p) {
    switch (index) {
    case 0: return texture(uShadowMaps2D[0], p);
    case 1: return texture(uShadowMaps2D[1], p);
    case 2: return texture(uShadowMaps2D[2], p);
    case 3: return texture(uShadowMaps2D[3], p);
    case 4: return texture(uShadowMaps2D[4], p);
    case 5: return texture(uShadowMaps2D[5], p);
    case 6: return texture(uShadowMaps2D[6], p);
    default: return texture(uShadowMaps2D[7], p);
    }
}

float compareCube(int index, vec4 p) {
    switch (index) {
    case 0: return texture(uShadowMapsCube[0], p);
    case 1: return texture(uShadowMapsCube[1], p);
    case 2: return texture(uShadowMapsCube[2], p);
    default: return texture(uShadowMapsCube[3], p);
    }
}

float shadowMap2D(int slot, int index, vec3 eyePosition) {
    vec4 coord = uShadowEyePlanes[slot] * vec4(eyePosition, 1.0);
    if (coord.w <= 0.0) return 0.0;
    vec3 p = coord.xyz / coord.w;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))))
        return uShadowParams[slot].w;
    if (p.z < 0.0) return 1.0;
    return compare2D(index, vec3(p.xy, min(p.z, 1.0)));
}

float shadowMapCube(int slot, int index, vec3 eyePosition) {
    vec3 toPoint = uShadowEyeToWorld * (eyePosition - uShadowPointLight[slot].xyz);
    float major = max(max(abs(toPoint.x), abs(toPoint.y)), abs(toPoint.z));
    float n = uShadowPointLight[slot].w, f = uShadowPointFar[slot];
    if (major < n) return 1.0;
    float depth = 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * major)) + 0.5;
    return compareCube(index, vec4(toPoint, min(depth, 1.0)));
}

vec2 lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {
    vec4 params = uShadowParams[lightSlot];
    int kind = int(params.x + 0.5);
    int index = int(params.y + 0.5);
    if (kind == SHADOW_2D) return vec2(shadowMap2D(lightSlot, index, eyePosition), params.z);
    if (kind == SHADOW_CUBE) return vec2(shadowMapCube(lightSlot, index, eyePosition), params.z);
    return vec2(params.w, params.z);
}
