// The shadow plugin's per-light visibility hook, inserted into the engine's lit fragment
// shader (see engine/render/Frame.h). It returns a light's shade (its dimming goes to the engine as a number):
//   2D maps (spot, directional): (s,t,r,q) = Ee * x_e, interpolated from the vertex part
//     (texgen.glsl), and the lookup's comparison of r/q with the map at (s/q, t/q);
//   cube maps (point): the major-axis depth of (x_world - light), also interpolated,
//     against the cube map.
// Points the map cannot speak for are decided here, explicitly, never by clamping:
//   q <= 0 (behind the light): never lit, no back-projection;
//   outside the map laterally: unlit for spot lights (outside the cone), lit for
//   directional lights (their frustum is fitted to every receiver the camera sees);
//   nearer than the near plane: lit (near is fitted to the nearest caster);
//   beyond the far plane: compared at r = 1, i.e. behind everything the map holds.
// A template: HookGlsl.cpp writes it once per lookup in use (technique/MapLookup.h), with
// $LOOKUP replaced by the lookup's GLSL name, after that lookup's own file (shaders/lookup/),
// which defines $LOOKUP2D, $LOOKUPArray and $LOOKUPCube, and $SAMPLER2D, $SAMPLERARRAY,
// $SAMPLERCUBE by the sampler types it reads (comparing ones, or plain ones for a lookup that
// compares depths itself). The plugin generates, after these,
// one sampler and one interpolated input per shadowed light (texture unit
// SHADOW_FIRST_UNIT + its slot) and lightVisibility() calling the functions below with
// constant slots: only the lookups a frame needs exist in the shader. (A generic version
// indexing sampler arrays cost llvmpipe 40 ms per 1280x720 frame even with every light
// unshadowed: it runs the texture fetches of untaken branches.)

// The per-light parameters come from shadow_data.glsl's block, and the map shapes' shared
// functions from map_shapes.glsl, both placed before this file.

// shadowMap2D is branch-free on purpose (selects, no early return): llvmpipe runs a fragment
// shader on SIMD lanes, and early returns cost it more than always sampling (measured:
// 34.6 -> 28 ms for one light at 1280x720). The cube-map functions are not: map_shapes.glsl's
// cubeReferenceDepth branches on a uniform (same way on every lane) and shadowMapCube
// returns early for points nearer than the near plane; neither was measured against a
// branch-free form.
// Reversed Z flips the depth range: nearer than near is r > 1, beyond far is r < 0, and
// "behind everything the map holds" is r = 0.
// coord: (s,t,r,q) from the vertex part (texgen.glsl), moved by the normal offset
// (map_shapes.glsl).
float shadowMap2D_$LOOKUP(int slot, vec4 coord, vec3 eyePosition, vec3 eyeNormal, $SAMPLER2D map) {
    coord = offsetShadowCoord(slot, coord, eyePosition, eyeNormal);
    vec3 p = coord.xyz / coord.w;
    bool reversed = shadowData.params[slot].x > 0.5;
    float reference = p.z - shadowData.params[slot].y;
    float shade = $LOOKUP2D(slot, map, p.xy, reversed ? max(reference, 0.0) : min(reference, 1.0));
    bool outside = any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)));
    shade = outside ? shadowData.params[slot].w : shade;
    shade = (reversed ? p.z > 1.0 : p.z < 0.0) ? 1.0 : shade;
    return coord.w <= 0.0 ? 0.0 : shade;
}

// One cascade's lookup (as shadowMap2D; never behind the light: an orthographic cascade's
// q is 1, a warped one's the distance along its warp axis, positive over its whole body).
float cascadeShade_$LOOKUP(int slot, vec3 eyePosition, vec3 eyeNormal, $SAMPLERARRAY map, int cascade) {
    vec3 p = offsetCascadeCoordinates(slot, eyePosition, eyeNormal, cascade, float(textureSize(map, 0).x));
    bool reversed = shadowData.params[slot].x > 0.5;
    float reference = p.z - shadowData.params[slot].y;
    float shade = $LOOKUPArray(slot, map, p.xy, cascade, reversed ? max(reference, 0.0) : min(reference, 1.0));
    bool outside = any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)));
    shade = outside ? shadowData.params[slot].w : shade;
    return (reversed ? p.z > 1.0 : p.z < 0.0) ? 1.0 : shade;
}

// With cascade_blend, just past a split the shade fades from the nearer cascade into the
// pixel's own (weight 0 at the split, 1 at the band's end), where the nearer map holds the
// point (a fitted cascade is fitted to reach over the band; math/CascadeFit.cpp).
float shadowMapCascades_$LOOKUP(int slot, vec3 eyePosition, vec3 eyeNormal, $SAMPLERARRAY map, int count) {
    // Past shadow_distance every point is lit, without a lookup; over its fade band the
    // shade fades toward lit.
    float fadeEnd = shadowData.cascadeBlend[slot].z, fadeStart = shadowData.cascadeBlend[slot].w;
    float fade = fadeEnd > 0.0 ? clamp((-eyePosition.z - fadeStart) / max(fadeEnd - fadeStart, 1e-30), 0.0, 1.0) : 0.0;
    if (fade >= 1.0) return 1.0;
    int cascade = cascadeIndex(slot, eyePosition, count);
    float shade = cascadeShade_$LOOKUP(slot, eyePosition, eyeNormal, map, cascade);
    float blend = shadowData.cascadeBlend[slot].x;
    if (blend > 0.0 && cascade > 0) {
        float start = shadowData.cascadeFar[slot][cascade - 1];
        float previousStart = cascade > 1 ? shadowData.cascadeFar[slot][cascade - 2] : shadowData.cascadeBlend[slot].y;
        float t = (-eyePosition.z - start) / (blend * (start - previousStart));
        vec2 nearer = cascadeCoordinates(slot, eyePosition, cascade - 1).xy;
        bool held = all(greaterThanEqual(nearer, vec2(0.0))) && all(lessThanEqual(nearer, vec2(1.0)));
        if (t < 1.0 && held) shade = mix(cascadeShade_$LOOKUP(slot, eyePosition, eyeNormal, map, cascade - 1), shade, max(t, 0.0));
    }
    return mix(shade, 1.0, fade);
}

// toPoint: light -> point along world axes, from the vertex part (texgen.glsl), moved by the
// normal offset.
float shadowMapCube_$LOOKUP(int slot, vec3 toPoint, vec3 eyePosition, vec3 eyeNormal, $SAMPLERCUBE map) {
    toPoint = offsetToPoint(slot, toPoint, eyePosition, eyeNormal);
    float major = cubeMajorAxisDistance(toPoint);
    if (major < shadowData.pointFar[slot].z) return 1.0;
    float depth = cubeBiasedReference(slot, major);
    bool reversed = shadowData.params[slot].x > 0.5;
    return $LOOKUPCube(slot, map, toPoint, reversed ? max(depth, 0.0) : min(depth, 1.0));
}
