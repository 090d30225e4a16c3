// The shadow plugin's per-light visibility hook, inserted into the engine's lit fragment
// shader (see engine/render/Frame.h). It returns a light's shade (its dimming goes to the engine as a number):
//   2D maps (spot, directional): (s,t,r,q) = Ee * x_e, interpolated from the vertex part
//     (texgen.glsl), and the hardware comparison r/q <= map(s/q, t/q) through a
//     sampler2DShadow (GL_LINEAR = 2x2 PCF);
//   cube maps (point): the major-axis depth of (x_world - light), also interpolated,
//     against a samplerCubeShadow.
// Points the map cannot speak for are decided here, explicitly, never by clamping:
//   q <= 0 (behind the light): never lit, no back-projection;
//   outside the map laterally: unlit for spot lights (outside the cone), lit for
//   directional lights (their frustum is fitted to every receiver the camera sees);
//   nearer than the near plane: lit (near is fitted to the nearest caster);
//   beyond the far plane: compared at r = 1, i.e. behind everything the map holds.
// The plugin generates, after this file, one sampler and one interpolated input per
// shadowed light (texture unit SHADOW_FIRST_UNIT + its slot) and lightVisibility() calling
// the functions below with constant slots: only the lookups a frame needs exist in the shader. (A generic version
// indexing sampler arrays cost llvmpipe 40 ms per 1280x720 frame even with every light
// unshadowed: it runs the texture fetches of untaken branches.)

// The per-light parameters come from shadow_data.glsl's block, placed before this file.

// shadowMap2D is branch-free on purpose (selects, no early return): llvmpipe runs a fragment
// shader on SIMD lanes, and early returns cost it more than always sampling (measured:
// 34.6 -> 28 ms for one light at 1280x720). The cube-map functions further down are not:
// cubeReferenceDepth branches on a uniform (same way on every lane) and shadowMapCube
// returns early for points nearer than the near plane; neither was measured against a
// branch-free form.
// Reversed Z flips the depth range: nearer than near is r > 1, beyond far is r < 0, and
// "behind everything the map holds" is r = 0.
// coord: (s,t,r,q) from the vertex part (texgen.glsl).
float shadowMap2D(int slot, vec4 coord, sampler2DShadow map) {
    vec3 p = coord.xyz / coord.w;
    bool reversed = shadowData.params[slot].x > 0.5;
    float reference = p.z - shadowData.params[slot].y;
    float shade = texture(map, vec3(p.xy, reversed ? max(reference, 0.0) : min(reference, 1.0)));
    bool outside = any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)));
    shade = outside ? shadowData.params[slot].w : shade;
    shade = (reversed ? p.z > 1.0 : p.z < 0.0) ? 1.0 : shade;
    return coord.w <= 0.0 ? 0.0 : shade;
}

// Cascaded directional maps (a sampler2DArrayShadow, one layer per cascade): the cascade is
// the first whose far split lies beyond the pixel's view depth (the last one for anything
// farther), and its coordinates come from that cascade's eye planes, per pixel: four
// cascades' interpolated coordinates would cost 16 varyings per light. The planes are
// camera-relative (Ee = Epo * V), so the float product is as precise as texgen.glsl's.
// Otherwise as shadowMap2D, orthographic (q = 1, never behind the light).
int cascadeIndex(int slot, vec3 eyePosition, int count) {
    vec4 passed = vec4(greaterThan(vec4(-eyePosition.z), shadowData.cascadeFar[slot]));
    return min(int(dot(passed, vec4(1.0))), count - 1);
}

vec3 cascadeCoordinates(int slot, vec3 eyePosition, int cascade) {
    return (shadowData.cascadePlanes[slot * MAX_CASCADES + cascade] * vec4(eyePosition, 1.0)).xyz;
}

// One cascade's lookup (as shadowMap2D, orthographic: q = 1, never behind the light).
float cascadeShade(int slot, vec3 eyePosition, sampler2DArrayShadow map, int cascade) {
    vec3 p = cascadeCoordinates(slot, eyePosition, cascade);
    bool reversed = shadowData.params[slot].x > 0.5;
    float reference = p.z - shadowData.params[slot].y;
    float shade = texture(map, vec4(p.xy, float(cascade), reversed ? max(reference, 0.0) : min(reference, 1.0)));
    bool outside = any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)));
    shade = outside ? shadowData.params[slot].w : shade;
    return (reversed ? p.z > 1.0 : p.z < 0.0) ? 1.0 : shade;
}

// With cascade_blend, just past a split the shade fades from the nearer cascade into the
// pixel's own (weight 0 at the split, 1 at the band's end), where the nearer map holds the
// point (a fitted cascade is fitted to reach over the band; math/CascadeFit.cpp).
float shadowMapCascades(int slot, vec3 eyePosition, sampler2DArrayShadow map, int count) {
    int cascade = cascadeIndex(slot, eyePosition, count);
    float shade = cascadeShade(slot, eyePosition, map, cascade);
    float blend = shadowData.cascadeBlend[slot].x;
    if (blend > 0.0 && cascade > 0) {
        float start = shadowData.cascadeFar[slot][cascade - 1];
        float previousStart = cascade > 1 ? shadowData.cascadeFar[slot][cascade - 2] : shadowData.cascadeBlend[slot].y;
        float t = (-eyePosition.z - start) / (blend * (start - previousStart));
        vec2 nearer = cascadeCoordinates(slot, eyePosition, cascade - 1).xy;
        bool held = all(greaterThanEqual(nearer, vec2(0.0))) && all(lessThanEqual(nearer, vec2(1.0)));
        if (t < 1.0 && held) shade = mix(cascadeShade(slot, eyePosition, map, cascade - 1), shade, max(t, 0.0));
    }
    return shade;
}

// The distance from the light along the major axis of toPoint = x_world - light: the cube
// face that holds the texel is the one of the largest |component| (OpenGL 4.5 table 8.19),
// and its perspective depth is this distance.
float cubeMajorAxisDistance(vec3 toPoint) {
    return max(max(abs(toPoint.x), abs(toPoint.y)), abs(toPoint.z));
}

// The window depth a cube face wrote at distance `major` along its axis, in forms that keep
// float's relative precision: f/(f-n) * (1 - n/major), or reversed n/(f-n) * (f/major - 1)
// (the same numbers as 0.5 * ((f+n)/(f-n) - 2fn/((f-n) major)) + 0.5, fewer roundings);
// with an infinite far (f = 0 here): 1 - n/major, reversed n/major. Its CPU twin is
// cubeShadowReferenceDepth (math/LightFrustum.h); CubeReferenceDepthTest compares the two.
float cubeReferenceDepth(int slot, float major) {
    float n = shadowData.pointLight[slot].w, f = shadowData.pointFar[slot].x;
    bool reversed = shadowData.params[slot].x > 0.5;
    if (f <= 0.0) return reversed ? n / major : 1.0 - n / major;
    return reversed ? n / (f - n) * (f / major - 1.0) : f / (f - n) * (1.0 - n / major);
}

// The comparison view of Kilgard's GDC 2000 slides, for engine-render --shadow-compare: green where the
// reference depth r and the map's depth agree (the surface is the one the light sees
// first: lit), red where the map holds something nearer (shadowed), blue where it holds
// something farther (r in front of the map: polygon offset or peeling at work), grey where
// the map has no say (behind the light, outside its frustum).
// In window depth: about the polygon offset of a moderately sloped surface at 2048 texels
// (2 x one texel of slope + 8 units), so an offset lit surface shows green and only
// grazing ones, where the offset grows with the slope, turn blue.
const float kDepthAgreement = 1e-3;

vec4 comparisonColor(float reference, float stored) {
    if (abs(reference - stored) <= kDepthAgreement) return vec4(0.1, 0.8, 0.1, 1.0);
    return reference > stored ? vec4(0.85, 0.1, 0.1, 1.0) : vec4(0.1, 0.2, 0.9, 1.0);
}

vec4 comparison2D(int slot, vec4 coord, sampler2D depth) {
    vec3 p = coord.xyz / coord.w;
    if (coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0))))
        return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(depth, p.xy).r;
    // Reversed Z: nearer is larger, so the roles swap for "reference behind stored".
    return shadowData.params[slot].x > 0.5 ? comparisonColor(stored, p.z) : comparisonColor(p.z, stored);
}

vec4 comparisonCascades(int slot, vec3 eyePosition, sampler2DArray depth, int count) {
    int cascade = cascadeIndex(slot, eyePosition, count);
    vec3 p = (shadowData.cascadePlanes[slot * MAX_CASCADES + cascade] * vec4(eyePosition, 1.0)).xyz;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(depth, vec3(p.xy, float(cascade))).r;
    return shadowData.params[slot].x > 0.5 ? comparisonColor(stored, p.z) : comparisonColor(p.z, stored);
}

// The depth a point at `major` along its cube face's axis is compared with: its window depth
// minus the lookup's biases, so the comparison view judges exactly what the lookup judges.
float cubeBiasedReference(int slot, float major) {
    float depth = cubeReferenceDepth(slot, major) - shadowData.params[slot].y;
    bool reversed = shadowData.params[slot].x > 0.5;
    // Lowered by the depth a 45-degree surface spans across kCubeTexelBias texels here
    // (CubeMapProjection.cpp says why): d(depth)/d(major) times a texel's width, 2 major / res
    // (pointFar.y holds kCubeTexelBias * 2 / res), so the bias is a fixed part of a texel at
    // every distance; the window depth grows with major as n f / ((f - n) major^2), or n / major^2
    // with an infinite far, and falls (reversed Z) as fast.
    float n = shadowData.pointLight[slot].w, f = shadowData.pointFar[slot].x;
    float texelBias = (f <= 0.0 ? n / major : n * f / ((f - n) * major)) * shadowData.pointFar[slot].y;
    return depth + (reversed ? texelBias : -texelBias);
}

vec4 comparisonCube(int slot, vec3 toPoint, samplerCube depth) {
    float major = cubeMajorAxisDistance(toPoint);
    float reference = cubeReferenceDepth(slot, major);
    bool reversed = shadowData.params[slot].x > 0.5;
    if (major < shadowData.pointLight[slot].w || (reversed ? reference < 0.0 : reference > 1.0))
        return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(depth, toPoint).r;
    float biased = cubeBiasedReference(slot, major);
    return reversed ? comparisonColor(stored, biased) : comparisonColor(biased, stored);
}

// toPoint: light -> point along world axes, from the vertex part (texgen.glsl).
float shadowMapCube(int slot, vec3 toPoint, samplerCubeShadow map) {
    float major = cubeMajorAxisDistance(toPoint);
    if (major < shadowData.pointLight[slot].w) return 1.0;
    float depth = cubeBiasedReference(slot, major);
    bool reversed = shadowData.params[slot].x > 0.5;
    return texture(map, vec4(toPoint, reversed ? max(depth, 0.0) : min(depth, 1.0)));
}
