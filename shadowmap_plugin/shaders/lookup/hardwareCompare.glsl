// The texture unit's depth comparison, one fetch through a comparing sampler: `reference`
// against the map at the point, 1 where it is not behind the stored depth. With GL_NEAREST
// it compares one texel; with GL_LINEAR the four around the point and interpolates the
// results bilinearly (2x2 percentage-closer filtering). `reference` is biased and clamped;
// the light's slot is not needed.
float hardwareCompare2D(int slot, sampler2DShadow map, vec2 st, float reference) {
    return texture(map, vec3(st, reference));
}

float hardwareCompareArray(int slot, sampler2DArrayShadow map, vec2 st, int layer, float reference) {
    return texture(map, vec4(st, float(layer), reference));
}

float hardwareCompareCube(int slot, samplerCubeShadow map, vec3 toPoint, float reference) {
    return texture(map, vec4(toPoint, reference));
}
