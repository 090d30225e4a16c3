// The shadow plugin's visibility hook for the clustered lit pass (engine/render/Frame.h):
// called with a light slot that is not a constant, so every light's map lives in one atlas
// texture (plugin/AtlasMaps.h) and its parameters in another, a row of eight texels per
// light (a texture, not a storage buffer: engine/render/Frame.h says why). ATLAS_UNIT,
// ATLAS_DEPTH_UNIT and ATLAS_LIGHTS_UNIT are defined by the plugin (AtlasMaps.cpp).
//
// The lookup is shadowMap2D's (visibility.glsl) with the hardware comparison, the
// coordinates computed per pixel from the eye planes (no per-light interpolated inputs: a
// tile's lights are not known to the vertex stage), then moved into the light's rectangle of
// the atlas and clamped half a texel inside it, so the 2x2 comparison reads only its own
// map's texels, as clamp-to-edge would at a map's own edge.
struct AtlasLight {
    mat4 eyePlanes;   // Ee, rows s,t,r,q into the light's own [0,1] map (texgen.glsl)
    vec4 rect;        // the map's rectangle in the atlas: xy its lower corner, zw its size (atlas [0,1] units)
    vec4 params;      // x: 1 = reversed Z; y: reference bias; z: normal_offset in texels; w: the shade
                      // outside the map, or everywhere when the light has no map (kind 0)
    vec4 lightInEye;  // as shadow_data.glsl's lightInEye
    vec4 texel;       // xy: texelWidths.xy as shadow_data.glsl's; z: half an atlas texel; w: 1 = a map
};
layout(binding = ATLAS_LIGHTS_UNIT) uniform sampler2D atlasLightData;
AtlasLight atlasLightAt(int slot) {
    vec4 row[8];
    for (int i = 0; i < 8; ++i) row[i] = texelFetch(atlasLightData, ivec2(i, slot), 0);
    return AtlasLight(mat4(row[0], row[1], row[2], row[3]), row[4], row[5], row[6], row[7]);
}
layout(binding = ATLAS_UNIT) uniform sampler2DShadow shadowAtlas;
layout(binding = ATLAS_DEPTH_UNIT) uniform sampler2D shadowAtlasDepth;

// (s,t,r,q) at the point moved along its normal by normal_offset texels times the sine of the
// angle to the light (map_shapes.glsl's normalOffset and offsetShadowCoord).
vec4 atlasShadowCoord(AtlasLight light, vec3 eyePosition, vec3 eyeNormal) {
    vec4 coord = light.eyePlanes * vec4(eyePosition, 1.0);
    float texelWidth = max(light.texel.x * coord.w, light.texel.y * coord.w * coord.w);
    vec3 toLight = normalize(light.lightInEye.w > 0.5 ? light.lightInEye.xyz - eyePosition : light.lightInEye.xyz);
    float cosine = clamp(dot(eyeNormal, toLight), -1.0, 1.0);
    vec3 offset = eyeNormal * (light.params.z * texelWidth * sqrt(1.0 - cosine * cosine));
    return coord + light.eyePlanes * vec4(offset, 0.0);
}

// The map coordinate p.xy in [0,1] as a point of the atlas, kept half a texel inside the
// light's rectangle.
vec2 atlasPoint(AtlasLight light, vec2 mapPoint) {
    vec2 lower = light.rect.xy + light.texel.z, upper = light.rect.xy + light.rect.zw - light.texel.z;
    return clamp(light.rect.xy + mapPoint * light.rect.zw, lower, upper);
}

float lightVisibility(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {
    // A light without a map: its one shade, before fetching the rest of its row.
    if (texelFetch(atlasLightData, ivec2(7, lightSlot), 0).w < 0.5)
        return texelFetch(atlasLightData, ivec2(5, lightSlot), 0).w;
    AtlasLight light = atlasLightAt(lightSlot);
    vec4 coord = atlasShadowCoord(light, eyePosition, eyeNormal);
    vec3 p = coord.xyz / coord.w;
    bool reversed = light.params.x > 0.5;
    float reference = p.z - light.params.y;
    float shade = texture(shadowAtlas, vec3(atlasPoint(light, p.xy), reversed ? max(reference, 0.0) : min(reference, 1.0)));
    bool outside = any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)));
    shade = outside ? light.params.w : shade;
    shade = (reversed ? p.z > 1.0 : p.z < 0.0) ? 1.0 : shade;
    return coord.w <= 0.0 ? 0.0 : shade;
}

vec4 lightDebugColor(int lightSlot, vec3 eyePosition, vec3 eyeNormal) {
    AtlasLight light = atlasLightAt(lightSlot);
    vec4 coord = atlasShadowCoord(light, eyePosition, eyeNormal);
    vec3 p = coord.xyz / coord.w;
    if (light.texel.w < 0.5 || coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0))))
        return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(shadowAtlasDepth, atlasPoint(light, p.xy)).r;
    return light.params.x > 0.5 ? comparisonColor(stored, p.z) : comparisonColor(p.z, stored);
}
