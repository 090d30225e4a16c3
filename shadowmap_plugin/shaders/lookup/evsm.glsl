// Exponential variance shadow maps (technique/lookup/MomentsLookup.h): the moments of both of
// EVSM's warps of the depth (moments.glsl), one filtered fetch, and the smaller of the two
// Chebyshev bounds at the receiver's warped depths, with the light-bleeding reduction of
// lookupParams.x; lookupParams.yz hold the positive and negative exponents. Sampled as
// vsm.glsl samples.

float evsmShade(int slot, vec4 moments, float u) {
    vec2 warped = evsmWarp(u, shadowData.lookupParams[slot].yz);
    float positive = chebyshevUpperBound(moments.xy, warped.x);
    // The negative warp grows toward the light: -e^(-c x) rises with u, as the bound needs.
    float negative = chebyshevUpperBound(moments.zw, warped.y);
    return reduceBleeding(min(positive, negative), shadowData.lookupParams[slot].x);
}

float evsm2D(int slot, sampler2D map, vec2 st, float reference) {
    return evsmShade(slot, texture(map, st), momentsReceiverDepth(slot, 0, reference));
}

float evsmArray(int slot, sampler2DArray map, vec2 st, int layer, float reference) {
    return evsmShade(slot, textureLod(map, vec3(st, float(layer)), 0.0), momentsReceiverDepth(slot, layer, reference));
}

float evsmCube(int slot, samplerCube map, vec3 toPoint, float reference) {
    return evsmShade(slot, textureLod(map, toPoint, 0.0), momentsReceiverDepth(slot, 0, reference));
}
