// What every lookup of the shadow plugin shares, whatever it fetches from the map: picking
// a cascade and its coordinates, a cube face's reference depth and its bias, and the
// comparison view (engine-render --shadow-compare). Placed after shadow_data.glsl's block and
// before each lookup's instance of visibility.glsl.

// Cascaded directional maps (a sampler2DArrayShadow, one layer per cascade): the cascade is
// the first whose far split lies beyond the pixel's view depth (the last one for anything
// farther), and its coordinates come from that cascade's eye planes, per pixel: four
// cascades' interpolated coordinates would cost 16 varyings per light. The planes are
// camera-relative (Ee = Epo * V), so the float product is as precise as texgen.glsl's.
int cascadeIndex(int slot, vec3 eyePosition, int count) {
    vec4 passed = vec4(greaterThan(vec4(-eyePosition.z), shadowData.cascadeFar[slot]));
    return min(int(dot(passed, vec4(1.0))), count - 1);
}

// A cascade's (s, t, r) at an eye-space point; q is 1 for an orthographic cascade (the
// divide is exact then) and the distance along the warp axis for a warped one (lispsm).
vec3 cascadeCoordinates(int slot, vec3 eyePosition, int cascade) {
    vec4 coord = shadowData.cascadePlanes[slot * MAX_CASCADES + cascade] * vec4(eyePosition, 1.0);
    return coord.xyz / coord.w;
}

// Whether a cascade is warped (lispsm): its q row depends on the position.
bool cascadeIsWarped(mat4 planes) { return planes[0][3] != 0.0 || planes[1][3] != 0.0 || planes[2][3] != 0.0; }

// The width of a texel of a projective map at the eye-space point whose coordinates under
// `planes` are `coord`: one texel (1/resolution) of s or t over the length of its gradient,
// d(s/q) = (row_s - (s/q) row_q) / q, the wider of the two.
float projectiveTexelWidth(mat4 planes, vec4 coord, float resolution) {
    vec3 rowS = vec3(planes[0][0], planes[1][0], planes[2][0]);
    vec3 rowT = vec3(planes[0][1], planes[1][1], planes[2][1]);
    vec3 rowQ = vec3(planes[0][3], planes[1][3], planes[2][3]);
    vec2 st = coord.xy / coord.w;
    float gradient = min(length(rowS - st.x * rowQ), length(rowT - st.y * rowQ));
    return abs(coord.w) / (resolution * gradient);
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
    float n = shadowData.pointFar[slot].z, f = shadowData.pointFar[slot].x;
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

// Normal-offset bias: the receiver moved along its normal, in eye space, by normal_offset
// texels of width `texelWidth` (the map's at the receiver) times the sine of the angle
// between the normal and the light: nothing where the surface faces the light (the depth
// bias suffices there), the most at grazing light, where a texel's depth step is largest.
// Zero when normal_offset is 0. eyeNormal is unit length.
vec3 normalOffset(int slot, vec3 eyePosition, vec3 eyeNormal, float texelWidth) {
    vec4 light = shadowData.lightInEye[slot];
    vec3 toLight = normalize(light.w > 0.5 ? light.xyz - eyePosition : light.xyz);
    float cosine = clamp(dot(eyeNormal, toLight), -1.0, 1.0);
    return eyeNormal * (shadowData.lookupParams[slot].w * texelWidth * sqrt(1.0 - cosine * cosine));
}

// The point each map shape's lookup compares, moved by the normal offset. Texgen is linear,
// so an eye-space step d moves a 2D map's (s,t,r,q) by Ee * (d, 0); a cube's light-to-point
// vector by d turned to world axes.
vec4 offsetShadowCoord(int slot, vec4 coord, vec3 eyePosition, vec3 eyeNormal) {
    vec2 widths = shadowData.texelWidths[slot].xy;
    float texelWidth = max(widths.x * coord.w, widths.y * coord.w * coord.w);
    vec3 offset = normalOffset(slot, eyePosition, eyeNormal, texelWidth);
    return coord + shadowData.eyePlanes[slot] * vec4(offset, 0.0);
}

// An orthographic cascade's texel is as wide everywhere (texelWidths); a warped one's grows
// along its warp, so it is measured at the point (no room in the block for a per-cascade
// growth as the 2D map's: the block is at the 16 KiB every GL allows).
vec3 offsetCascadeCoordinates(int slot, vec3 eyePosition, vec3 eyeNormal, int cascade, float resolution) {
    mat4 planes = shadowData.cascadePlanes[slot * MAX_CASCADES + cascade];
    float texelWidth = cascadeIsWarped(planes)
                           ? projectiveTexelWidth(planes, planes * vec4(eyePosition, 1.0), resolution)
                           : shadowData.texelWidths[slot][cascade];
    vec3 offset = normalOffset(slot, eyePosition, eyeNormal, texelWidth);
    return cascadeCoordinates(slot, eyePosition + offset, cascade);
}

vec3 offsetToPoint(int slot, vec3 toPoint, vec3 eyePosition, vec3 eyeNormal) {
    float texelWidth = shadowData.texelWidths[slot].x * cubeMajorAxisDistance(toPoint);
    return toPoint + mat3(shadowData.eyeToWorld) * normalOffset(slot, eyePosition, eyeNormal, texelWidth);
}



vec4 comparison2D(int slot, vec4 coord, vec3 eyePosition, vec3 eyeNormal, sampler2D depth) {
    coord = offsetShadowCoord(slot, coord, eyePosition, eyeNormal);
    vec3 p = coord.xyz / coord.w;
    if (coord.w <= 0.0 || any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0))))
        return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(depth, p.xy).r;
    // Reversed Z: nearer is larger, so the roles swap for "reference behind stored".
    return shadowData.params[slot].x > 0.5 ? comparisonColor(stored, p.z) : comparisonColor(p.z, stored);
}

vec4 comparisonCascades(int slot, vec3 eyePosition, vec3 eyeNormal, sampler2DArray depth, int count) {
    int cascade = cascadeIndex(slot, eyePosition, count);
    vec3 p = offsetCascadeCoordinates(slot, eyePosition, eyeNormal, cascade, float(textureSize(depth, 0).x));
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
    float n = shadowData.pointFar[slot].z, f = shadowData.pointFar[slot].x;
    float texelBias = (f <= 0.0 ? n / major : n * f / ((f - n) * major)) * shadowData.pointFar[slot].y;
    return depth + (reversed ? texelBias : -texelBias);
}

vec4 comparisonCube(int slot, vec3 toPoint, vec3 eyePosition, vec3 eyeNormal, samplerCube depth) {
    toPoint = offsetToPoint(slot, toPoint, eyePosition, eyeNormal);
    float major = cubeMajorAxisDistance(toPoint);
    float reference = cubeReferenceDepth(slot, major);
    bool reversed = shadowData.params[slot].x > 0.5;
    if (major < shadowData.pointFar[slot].z || (reversed ? reference < 0.0 : reference > 1.0))
        return vec4(0.4, 0.4, 0.4, 1.0);
    float stored = texture(depth, toPoint).r;
    float biased = cubeBiasedReference(slot, major);
    return reversed ? comparisonColor(stored, biased) : comparisonColor(biased, stored);
}

// A moments lookup's receiver depth (vsm, evsm: moments.glsl's momentsDepth) from its biased,
// clamped window depth, with the layer's near and far from softLayers.zw.
float momentsReceiverDepth(int slot, int layer, float reference) {
    vec4 planes = shadowData.softLayers[slot * MAX_CASCADES + layer];
    return momentsDepth(reference, shadowData.lightInEye[slot].w > 0.5, shadowData.params[slot].x > 0.5,
                        planes.z, planes.w);
}
