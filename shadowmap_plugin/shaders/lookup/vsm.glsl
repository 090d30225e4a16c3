// Variance shadow maps (technique/lookup/MomentsLookup.h; Donnelly and Lauritzen, "Variance
// Shadow Maps", 2006): one filtered fetch of the moments (u, u^2) around the point, and
// Chebyshev's bound of the lit share at the receiver's depth (moments.glsl), with the light-
// bleeding reduction of lookupParams.x. The map is the light's moments texture, read through
// its own sampler: bilinear, and trilinear and anisotropic over a 2D map's mipmaps; a
// cascade's layer and a cube map read their first level (they are not mipmapped: their
// lookups follow a per-pixel branch, where GLSL leaves implicit derivatives undefined).

float vsmShade(int slot, vec4 moments, float u) {
    return reduceBleeding(chebyshevUpperBound(moments.xy, u), shadowData.lookupParams[slot].x);
}

float vsm2D(int slot, sampler2D map, vec2 st, float reference) {
    return vsmShade(slot, texture(map, st), momentsReceiverDepth(slot, 0, reference));
}

float vsmArray(int slot, sampler2DArray map, vec2 st, int layer, float reference) {
    return vsmShade(slot, textureLod(map, vec3(st, float(layer)), 0.0), momentsReceiverDepth(slot, layer, reference));
}

float vsmCube(int slot, samplerCube map, vec3 toPoint, float reference) {
    return vsmShade(slot, textureLod(map, toPoint, 0.0), momentsReceiverDepth(slot, 0, reference));
}
