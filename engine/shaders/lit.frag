// Lit pass, fragment stage: ambient + per-light glTF 2.0 metallic-roughness BRDF (the
// specification's Appendix B: GGX distribution, height-correlated Smith-GGX visibility,
// Schlick Fresnel, Lambert diffuse weighted by (1 - F) and (1 - metallic)), spot cone
// falloff and range attenuation as KHR_lights_punctual recommends, and the
// ambient-retaining modulate with the plugin's per-light visibility term (shadowed regions
// keep ambient and dimmed diffuse):
//   diffuseShade = d + (1 - d) * shade
//   color = emissive + ambient * albedo + sum(diffuseShade * diffuse + shade * specular)
// Light units: a light's color x intensity is taken as the irradiance it brings (lux for
// directional lights, candela / d^2 for the others); the radiance is multiplied by the
// renderer's exposure, tone mapped when TONE_MAPPING_PBR_NEUTRAL is defined (else the sRGB
// target clamps it at 1) and encoded by the sRGB target.
// The engine prepends "#version 450 core", MAX_LIGHTS and LIGHTS_BLOCK_BINDING (Frame.h),
// LIGHT_COUNT (the scene's lights)
// and FOR_EACH_LIGHT(F), which expands to F(slot, type) for every light, both literal
// numbers: the sum is written out term by term, never looped, so each term indexes the
// light data and the shades with constants and keeps only its own type's code. (A loop
// over LIGHT_COUNT with the types in a constant array cost llvmpipe nearly twice as much:
// showcase unshadowed frame 14.4-15.0 -> 8.1-8.8 ms at 1280x720, three alternating runs.)
// Then it appends the hook and, with at least one light, loadShades() (ShadeCache.h),
// which takes each light's shade from the hook or from the shade cache, with constant
// slots too, before the terms are summed.
// The clustered lit pass (CLUSTERED_LIGHTS, engine/render/LightTiles.h) instead loops over
// the lights of the pixel's screen tile, reading them from storage buffers, and asks the
// hook for each light's shade as it reaches it (LIGHT_COUNT is 0 there: nothing unrolled).
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_POINT = 2;
const float PI = 3.14159265358979;

struct LightData {
    vec4 positionRange;   // eye space position; w = range (0 = infinite)
    vec4 direction;       // eye space direction the light shines along; w: clustered, the type
    vec4 radiance;        // linear color * intensity
    vec4 cone;            // x = cos(outer), y = cos(inner); z: clustered, the dimming
};
#ifdef CLUSTERED_LIGHTS
// The clustered lit pass (engine/render/LightTiles.h): every light as four texels of a row,
// and per screen tile of LIGHT_TILE_SIZE pixels the (first, count) of its list of light
// slots, the lists TILE_LISTS_WIDTH to a row (textures: Frame.h says why).
layout(binding = LIGHT_DATA_UNIT) uniform sampler2D uLightData;
layout(binding = TILE_RANGES_UNIT) uniform usampler2D uTileRanges;
layout(binding = TILE_LIGHTS_UNIT) uniform usampler2D uTileLights;
LightData lightAt(int slot) {
    return LightData(texelFetch(uLightData, ivec2(0, slot), 0), texelFetch(uLightData, ivec2(1, slot), 0),
                     texelFetch(uLightData, ivec2(2, slot), 0), texelFetch(uLightData, ivec2(3, slot), 0));
}
#define LIGHT_DIMMING(slot) texelFetch(uLightData, ivec2(3, slot), 0).z
#else
layout(std140, binding = LIGHTS_BLOCK_BINDING) uniform Lights {
    LightData uLights[MAX_LIGHTS];
};
LightData lightAt(int slot) { return uLights[slot]; }
uniform float uLightDimming[MAX_LIGHTS];  // the visibility hook's d per light
#define LIGHT_DIMMING(slot) uLightDimming[slot]
#endif
uniform vec3 uAmbient;
#ifdef EXPOSURE
// Only when not 1: the multiply cost llvmpipe 3 % of the showcase's unshadowed frame (1280x720,
// alternating runs: 10.3-10.6 ms without it, 10.7-10.9 with it).
uniform float uExposure;
#endif

// The base color (factor, vertex color, texture), the alpha test and the surface
// (metalness, roughness, normal map, occlusion, emission: material_surface.glsl) come from
// the material parts the engine prepends (MaterialShading.h), each a program variant of its own:
// llvmpipe samples in untaken branches too (showcase, no textures, three alternating
// runs: unshadowed 8.10-8.17 -> 7.66-7.74 ms at 1280x720 once untextured materials got a
// program without the fetch), and a shader that can discard defers its depth writes past
// the shading (2CylinderEngine, no masked materials, unshadowed frame 24.95-25.43 ->
// 21.27-21.89 ms).
// Node extras "receive_shadows" and KHR_lights_shadows "receiveShadows": false opts out.
uniform bool uReceiveShadows;

// Without a view define: the shaded color. LIGHT_MASK_VIEW: the visibility hook's shade
// of light uMaskLight as gray; LIGHT_DEBUG_VIEW: the hook's debug picture of that light
// (green/red/blue depth agreement, as Kilgard's GDC 2000 slides show it). Each is its own
// program variant on purpose: llvmpipe runs the texture fetches of untaken branches, so a
// view selected by a uniform made every shaded frame pay for the mask's lookups too (measured: 68 -> 38 ms at 1280x720, three
// shadowed lights).
uniform int uMaskLight;

in vec3 vEyePosition;
in vec3 vEyeNormal;
layout(location = 0) out vec4 outColor;

float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal);
vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal);

float shadeOf(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {
    return uReceiveShadows ? lightVisibility(lightSlot, eyePosition, eyeNormal) : 1.0;
}

#if LIGHT_COUNT > 0
void loadShades(out float shades[LIGHT_COUNT], vec3 eyePosition, vec3 eyeNormal);
#endif

float rangeWindow(float distance, float range) {
    if (range <= 0.0) return 1.0;
    float ratio = distance / range;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window;
}

// One light's term of the sum above. Called with literal slot and type (FOR_EACH_LIGHT):
// each call keeps only its own type's code (no cone for a point light, no distance for a
// directional one) and reads uniforms at constant indices.
vec3 lightContribution(int slot, int type, float shade, vec3 N, vec3 V, float NdotV, vec3 diffuseColor,
                       vec3 f0, float alpha) {
    LightData light = lightAt(slot);
    vec3 L;
    float attenuation = 1.0;
    if (type == LIGHT_DIRECTIONAL) {
        L = -light.direction.xyz;
    } else {
        vec3 toLight = light.positionRange.xyz - vEyePosition;
        float distance = length(toLight);
        L = toLight / max(distance, 1e-20);
        attenuation = rangeWindow(distance, light.positionRange.w) / max(distance * distance, 1e-8);
        if (type == LIGHT_SPOT) {
            float cosAngle = dot(-L, light.direction.xyz);
            float t = clamp((cosAngle - light.cone.x) / max(light.cone.y - light.cone.x, 1e-4), 0.0, 1.0);
            attenuation *= t * t;
        }
    }
    float NdotL = dot(N, L);
    if (NdotL <= 0.0 || attenuation <= 0.0) return vec3(0.0);
    vec3 radiance = light.radiance.rgb * attenuation * NdotL;
    vec3 H = normalize(L + V);
    float VdotH = max(dot(V, H), 0.0);
    // GGX D written with |N x H|^2 for 1 - (N.H)^2: the same value, without the
    // cancellation that costs float its digits near the highlight's centre at small alpha.
    vec3 NxH = cross(N, H);
    float NdotH = max(dot(N, H), 0.0);
    float k = alpha / (dot(NxH, NxH) + NdotH * NdotH * alpha * alpha);
    float D = k * k / PI;
    float a2 = alpha * alpha;
    float visibility = 0.5 / (NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) +
                              NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2));
    float oneMinusVdotH = 1.0 - VdotH;
    float oneMinusVdotH2 = oneMinusVdotH * oneMinusVdotH;
    vec3 F = f0 + (1.0 - f0) * (oneMinusVdotH2 * oneMinusVdotH2 * oneMinusVdotH);
    vec3 diffuse = (1.0 - F) * diffuseColor / PI * radiance;
    vec3 specular = F * (D * visibility) * radiance;
    float dimming = LIGHT_DIMMING(slot);
    // d + (1 - d) * shade, written so that a constant shade of 1 (no shadows) folds away at
    // compile time whatever d is.
    float diffuseShade = 1.0 - (1.0 - dimming) * (1.0 - shade);
    return diffuseShade * diffuse + shade * specular;
}

#ifdef TONE_MAPPING_PBR_NEUTRAL
// Khronos PBR Neutral tone mapping: colors whose largest channel stays under 0.76 pass
// unchanged (after a small black-level offset), brighter ones are compressed toward 1 and
// desaturated as they approach it, so base colors keep their hue under bright light.
vec3 toneMap(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}
#else
vec3 toneMap(vec3 color) { return color; }
#endif

void main() {
    vec4 albedo = materialBaseColor();
#ifdef ALPHA_TEST
    discardBelowAlphaCutoff(albedo.a);
#endif

    vec3 N = normalize(vEyeNormal);
    // The interpolated normal decides visibility (the shadow lookups and masks); the normal
    // map only shades.
    vec3 shadingNormal = materialNormal(N);
    if (!gl_FrontFacing) {  // double-sided materials light their back side
        N = -N;
        shadingNormal = -shadingNormal;
    }
    vec3 V = normalize(-vEyePosition);

#if defined(LIGHT_DEBUG_VIEW)
    outColor = lightDebugColor(uMaskLight, vEyePosition, N);
    return;
#elif defined(LIGHT_MASK_VIEW)
    outColor = vec4(vec3(shadeOf(uMaskLight, vEyePosition, N)), 1.0);
    return;
#endif

    vec2 metallicRoughness = materialMetallicRoughness();
    float metallic = metallicRoughness.x, roughness = metallicRoughness.y;
    vec3 diffuseColor = albedo.rgb * (1.0 - metallic);
    vec3 f0 = mix(vec3(0.04), albedo.rgb, metallic);
    // A perfectly smooth surface under a punctual light is a Dirac highlight float cannot
    // hold: alpha (roughness^2) stops at 0.002, where D at the highlight's centre is ~8e4.
    float alpha = max(roughness * roughness, 0.002);
    // A normal turned away from the eye (interpolated normals at silhouettes) shades as grazing.
    float NdotV = max(dot(shadingNormal, V), 1e-4);

    vec3 color = materialEmissive() + materialOccludedAmbient(uAmbient * albedo.rgb);
#if defined(CLUSTERED_LIGHTS)
    // The lights of this pixel's tile, each shaded where the loop reaches it: a tile's list
    // is the same for its whole 16x16 block, so neighbouring lanes mostly take the same path.
    uvec2 range = texelFetch(uTileRanges, ivec2(gl_FragCoord.xy) / LIGHT_TILE_SIZE, 0).xy;
    for (uint i = 0u; i < range.y; ++i) {
        uint entry = range.x + i;
        int slot = int(texelFetch(uTileLights, ivec2(entry % uint(TILE_LISTS_WIDTH), entry / uint(TILE_LISTS_WIDTH)), 0).r);
        float shade = shadeOf(slot, vEyePosition, N);
        color += lightContribution(slot, int(texelFetch(uLightData, ivec2(1, slot), 0).w), shade, shadingNormal, V, NdotV,
                                   diffuseColor, f0, alpha);
    }
#elif LIGHT_COUNT > 0
    // Every light's shade first, outside the terms' branches: llvmpipe runs lookups in
    // divergent branches far slower (measured, three shadowed lights at 1280x720: lit
    // pass 50 -> 21 ms), and implicit-LOD sampling belongs in uniform control flow anyway.
    float shades[LIGHT_COUNT];
    loadShades(shades, vEyePosition, N);
    // Each light's term, its slot and type literals (FOR_EACH_LIGHT).
#define ADD_LIGHT(slot, type) color += lightContribution(slot, type, shades[slot], shadingNormal, V, NdotV, diffuseColor, f0, alpha);
    FOR_EACH_LIGHT(ADD_LIGHT)
#endif
#ifdef EXPOSURE
    color *= uExposure;
#endif
    outColor = vec4(toneMap(color), albedo.a);
}
