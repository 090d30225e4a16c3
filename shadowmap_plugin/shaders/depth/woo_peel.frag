// Woo's midpoint map, pass 2 (technique/depth/WooDepth.h): fragments at or in front of the
// nearest layer z1 (pass 1: same triangles, same transform, `invariant gl_Position`) are
// discarded, and the rest write the midpoint (z + z1) / 2. z1 went through the depth format
// (d16/d24 round to a fixed-point step), so "at z1" means within uPeelEpsilon: two steps of
// the format (d32f: four float steps near 1). Without it, the first layer's own fragments
// survived the peel where rounding put them a step behind z1, and the map held z1 + tiny:
// acne on most lit surfaces of the showcase.
// The depth test then keeps the nearest remaining layer z2, since the midpoint grows with
// z. The far plane counts as a last layer (woo_peel.vert), so a texel with one surface
// holds the midpoint between it and far; texels with no surface at all keep the clear
// value (far): nothing there to shadow.
layout(binding = DEPTH_INPUT_UNIT) uniform sampler2D uFirstLayer;  // this map layer's (or cube face's)
// Reversed Z (d32f): near is 1, far 0, so "behind z1" is smaller, and the epsilon is
// relative (uPeelEpsilon * z1): float depth there has relative, not absolute, steps.
uniform float uPeelEpsilon;

void writeDepthFragment() {
    float z1 = texelFetch(uFirstLayer, ivec2(gl_FragCoord.xy), 0).r;
    bool firstLayer = uReversedZ ? gl_FragCoord.z >= z1 - uPeelEpsilon * z1
                                 : gl_FragCoord.z <= z1 + uPeelEpsilon;
    if (firstLayer) discard;
    gl_FragDepth = 0.5 * (gl_FragCoord.z + z1);
}
