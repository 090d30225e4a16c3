// Percentage-closer filtering over a disk (technique/lookup/WidePcfLookup.h): filter_taps
// taps on a Vogel disk of filter_radius texels turned per pixel (disk_taps.glsl), each a 2x2
// bilinear hardware comparison against the receiver's own plane. shadow_data.glsl's
// lookupParams hold the radius (x) and the taps (z).

// A tap's reference: on the receiver's plane, clamped as the caller clamped the centre's
// (visibility.glsl).
float widePcfReference(int slot, float reference, vec2 gradient, vec2 offset) {
    float moved = reference + dot(gradient, offset);
    return shadowData.params[slot].x > 0.5 ? max(moved, 0.0) : min(moved, 1.0);
}

// The body of the 2D map's and one cascade's lookup (whose radius is in its own texels):
// FETCH(st, reference) is the comparison at one tap.
#define WIDE_PCF_BODY(FETCH)                                                                   \
    {                                                                                          \
        vec2 radius = vec2(shadowData.lookupParams[slot].x) / vec2(textureSize(map, 0).xy);    \
        int taps = int(shadowData.lookupParams[slot].z);                                       \
        vec2 gradient = receiverDepthGradient(vec3(st, reference));                            \
        float rotation = diskRotation();                                                       \
        float lit = 0.0;                                                                       \
        for (int i = 0; i < taps; ++i) {                                                       \
            vec2 offset = diskTap(i, taps, rotation) * radius;                                 \
            lit += FETCH(st + offset, widePcfReference(slot, reference, gradient, offset));    \
        }                                                                                      \
        return lit / float(taps);                                                              \
    }
#define WIDE_PCF_FETCH_2D(tap, r) texture(map, vec3(tap, r))
#define WIDE_PCF_FETCH_ARRAY(tap, r) texture(map, vec4(tap, float(layer), r))

float widePcf2D(int slot, sampler2DShadow map, vec2 st, float reference) WIDE_PCF_BODY(WIDE_PCF_FETCH_2D)

float widePcfArray(int slot, sampler2DArrayShadow map, vec2 st, int layer, float reference)
    WIDE_PCF_BODY(WIDE_PCF_FETCH_ARRAY)

// A cube map: offsets on the face's plane at unit distance along the major axis, where a
// texel is 2 / resolution wide.
float widePcfCube(int slot, samplerCubeShadow map, vec3 toPoint, float reference) {
    float radius = 2.0 * shadowData.lookupParams[slot].x / float(textureSize(map, 0).x);
    int taps = int(shadowData.lookupParams[slot].z);
    vec3 direction = toPoint / cubeMajorAxisDistance(toPoint);
    vec3 across, up;
    cubeFaceAxes(toPoint, across, up);
    vec2 gradient = receiverDepthGradient(vec3(dot(direction, across), dot(direction, up), reference));
    float rotation = diskRotation();
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = diskTap(i, taps, rotation) * radius;
        lit += texture(map, vec4(direction + offset.x * across + offset.y * up,
                                 widePcfReference(slot, reference, gradient, offset)));
    }
    return lit / float(taps);
}
