// Percentage-closer soft shadows (technique/lookup/PcssLookup.h), read through plain samplers
// (comparison off): a blocker search over where the light's edge can be hidden from the
// receiver, the blockers' mean distance, and a filter as wide as the penumbra that distance
// makes (similar triangles). The light's size per layer and the depth-to-distance terms come
// from shadow_data.glsl's softLayers, lookupParams and lightInEye.
// Every tap compares against the receiver's own plane (disk_taps.glsl), so the polygon
// offset stays the 2x2 filter's. Search and filter reach at most kPcssMaxRadiusTexels
// texels of the light's first layer (technique/lookup/PcssLookup.h says why).

bool pcssPerspective(int slot) { return shadowData.lightInEye[slot].w > 0.5; }

// The distance of window depth z: from the light along the view axis (perspective, the
// inverse of the projection's depth, reversed or not, far 0 = infinite), or from the near
// plane (orthographic: layer.w holds the depth range).
float pcssDistance(int slot, vec4 layer, float z) {
    bool reversed = shadowData.params[slot].x > 0.5;
    float n = layer.z, f = layer.w;
    if (!pcssPerspective(slot)) return (reversed ? 1.0 - z : z) * f;
    if (f <= 0.0) return reversed ? n / max(z, 1e-30) : n / max(1.0 - z, 1e-30);
    return reversed ? n * f / (z * (f - n) + n) : n * f / (f - z * (f - n));
}

// How far the light's edge spreads, per unit of the layer's softLayers.xy, between a receiver
// and a blocker at these distances: (dR - dB) / (dR dB) for a light of a radius at the
// centre of a perspective view, dR - dB for an orthographic one.
float pcssSpread(int slot, float receiver, float blocker) {
    float behind = max(receiver - blocker, 0.0);
    return pcssPerspective(slot) ? behind / (receiver * max(blocker, 1e-30)) : behind;
}

// The nearest a blocker can be: the near plane (perspective) or the map's front (orthographic).
float pcssNearestBlocker(int slot, vec4 layer) { return pcssPerspective(slot) ? layer.z : 0.0; }

// 1 for each of four depths that lies in front of `reference` (a blocker), 0 where it does
// not (lit). Only blockers' depths become distances: the cleared far of an empty texel
// would be an infinite distance (0 * inf is NaN).
vec4 pcssInFront(vec4 depths, float reference, bool reversed) {
    return reversed ? vec4(greaterThan(depths, vec4(reference))) : vec4(lessThan(depths, vec4(reference)));
}

// The widest search and filter radius in map coordinates of a layer: kPcssMaxRadiusTexels
// texels of the light's first layer, so that a cascade's coarser texels reach no farther in
// the world than the first cascade's (a limit in each layer's own texels would let the
// penumbra widen at a split), and never under one texel of the layer itself.
vec2 pcssWidestRadius(int slot, int layer, float texels) {
    float firstLayerTexels = layer == 0 ? 1.0 : shadowData.texelWidths[slot].x / shadowData.texelWidths[slot][layer];
    return vec2(max(kPcssMaxRadiusTexels * firstLayerTexels, 1.0) / texels);
}

vec4 pcssGather(sampler2D map, vec2 st, int layer) { return textureGather(map, st); }
vec4 pcssGather(sampler2DArray map, vec2 st, int layer) { return textureGather(map, vec3(st, float(layer))); }

// A 2x2 comparison bilinearly weighted, as a comparing GL_LINEAR sampler gives it: `lit` of
// the texels textureGather returns ((0,1), (1,1), (1,0), (0,0)) around st.
float pcssBilinear(vec4 lit, vec2 st, float texels) {
    vec2 f = fract(st * texels - 0.5);
    return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// The mean distance of the blockers in front of the receiver within the search disk
// (distance 0 where there are none), for a 2D map or one cascade's layer; the same code for
// both samplers (pcssGather's overloads).
#define PCSS_BLOCKER_DISTANCE(SAMPLER)                                                          \
    float pcssBlockerDistance(int slot, SAMPLER map, vec2 st, int layer, float reference,        \
                              vec2 gradient, vec2 searchRadius, float rotation) {                \
        bool reversed = shadowData.params[slot].x > 0.5;                                         \
        vec4 scale = shadowData.softLayers[slot * MAX_CASCADES + layer];                         \
        int taps = int(shadowData.lookupParams[slot].y);                                        \
        float sum = 0.0, count = 0.0;                                                            \
        for (int i = 0; i < taps; ++i) {                                                         \
            vec2 offset = diskTap(i, taps, rotation) * searchRadius;                         \
            vec4 depths = pcssGather(map, st + offset, layer);                                   \
            vec4 inFront = pcssInFront(depths, reference + dot(gradient, offset), reversed);     \
            for (int k = 0; k < 4; ++k) sum += inFront[k] > 0.0 ? pcssDistance(slot, scale, depths[k]) : 0.0; \
            count += dot(inFront, vec4(1.0));                                                    \
        }                                                                                        \
        return count > 0.0 ? sum / count : 0.0;                                                  \
    }
PCSS_BLOCKER_DISTANCE(sampler2D)
PCSS_BLOCKER_DISTANCE(sampler2DArray)

// The shade of a 2D map or one cascade's layer.
#define PCSS_SHADE(SAMPLER)                                                                       \
    float pcssShade(int slot, SAMPLER map, vec2 st, int layer, float reference) {                \
        bool reversed = shadowData.params[slot].x > 0.5;                                          \
        vec4 scale = shadowData.softLayers[slot * MAX_CASCADES + layer];                          \
        float texels = float(textureSize(map, 0).x);                                              \
        int taps = int(shadowData.lookupParams[slot].z);                                          \
        float receiver = pcssDistance(slot, scale, reference);                                    \
        vec2 gradient = receiverDepthGradient(vec3(st, reference));                                   \
        float rotation = diskRotation();                                                          \
        vec2 widest = pcssWidestRadius(slot, layer, texels);                                      \
        vec2 searchRadius = min(scale.xy * pcssSpread(slot, receiver, pcssNearestBlocker(slot, scale)), widest); \
        float blocker = pcssBlockerDistance(slot, map, st, layer, reference, gradient, searchRadius, rotation); \
        if (blocker <= 0.0) return 1.0;                                                            \
        /* no wider than the search; a penumbra under a texel shrinks the taps onto st, so a    \
           small light shades as the 2x2 filter does instead of blurred a texel wide */          \
        vec2 radius = min(scale.xy * pcssSpread(slot, receiver, blocker), widest);                 \
        float lit = 0.0;                                                                           \
        for (int i = 0; i < taps; ++i) {                                                           \
            vec2 tap = st + diskTap(i, taps, rotation) * radius;                               \
            vec4 inFront = pcssInFront(pcssGather(map, tap, layer), reference + dot(gradient, tap - st), reversed); \
            lit += pcssBilinear(vec4(1.0) - inFront, tap, texels);                                 \
        }                                                                                          \
        return lit / float(taps);                                                                  \
    }
PCSS_SHADE(sampler2D)
PCSS_SHADE(sampler2DArray)

float pcss2D(int slot, sampler2D map, vec2 st, float reference) { return pcssShade(slot, map, st, 0, reference); }

float pcssArray(int slot, sampler2DArray map, vec2 st, int layer, float reference) {
    return pcssShade(slot, map, st, layer, reference);
}

// A cube map: offsets move the direction on its face's plane at unit distance along the
// major axis, so they are tangents of that face, the face's own map coordinates (times 2),
// and the cube's layer holds the light's radius in them. Each tap compares the four texels
// textureGather returns, unweighted (face coordinates for bilinear weights are not worth
// their cost here).
float pcssCube(int slot, samplerCube map, vec3 toPoint, float reference) {
    bool reversed = shadowData.params[slot].x > 0.5;
    vec4 scale = shadowData.softLayers[slot * MAX_CASCADES];
    int searchTaps = int(shadowData.lookupParams[slot].y), taps = int(shadowData.lookupParams[slot].z);
    float major = cubeMajorAxisDistance(toPoint);
    vec3 direction = toPoint / major;
    vec3 across, up;
    cubeFaceAxes(toPoint, across, up);
    vec2 gradient = receiverDepthGradient(vec3(dot(direction, across), dot(direction, up), reference));
    float rotation = diskRotation();
    // A texel is 2 / texels wide in tangent units. A search disk wider than 45 degrees would
    // look into other faces for blockers that cannot hide this light's edge: capped at one
    // tangent too.
    float texelWidth = 2.0 / float(textureSize(map, 0).x);
    float widest = min(kPcssMaxRadiusTexels * texelWidth, 1.0);
    float searchRadius = min(scale.x * pcssSpread(slot, major, pcssNearestBlocker(slot, scale)), widest);
    float sum = 0.0, count = 0.0;
    for (int i = 0; i < searchTaps; ++i) {
        vec2 offset = diskTap(i, searchTaps, rotation) * searchRadius;
        vec4 depths = textureGather(map, direction + offset.x * across + offset.y * up);
        vec4 inFront = pcssInFront(depths, reference + dot(gradient, offset), reversed);
        for (int k = 0; k < 4; ++k) sum += inFront[k] > 0.0 ? pcssDistance(slot, scale, depths[k]) : 0.0;
        count += dot(inFront, vec4(1.0));
    }
    if (count == 0.0) return 1.0;
    float radius = min(scale.x * pcssSpread(slot, major, sum / count), widest);
    float lit = 0.0;
    for (int i = 0; i < taps; ++i) {
        vec2 offset = diskTap(i, taps, rotation) * radius;
        vec4 depths = textureGather(map, direction + offset.x * across + offset.y * up);
        lit += 1.0 - 0.25 * dot(pcssInFront(depths, reference + dot(gradient, offset), reversed), vec4(1.0));
    }
    return lit / float(taps);
}
