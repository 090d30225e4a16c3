// The first moments pass of a map layer (plugin/MomentsRenderer.h): each texel's moments
// (moments.glsl) of the depth map's texels along uStep, averaged with the box weights of the
// blur's radius; with radius 0, the texel's own. The depth map is read through a 2D-array
// view (a 2D map as one layer, a cube's faces as six), texel by texel, clamped at the edges.
layout(binding = 0) uniform sampler2DArray uDepth;
uniform int uLayer;
uniform ivec2 uStep;        // (1, 0): along s; the second pass (moments_blur.frag) goes along t
uniform float uRadius;      // texels each side; the texel past floor(radius) weighs its fraction
uniform bool uPerspective;  // the layer's depth is a perspective one (spot light, cube face)
uniform bool uReversed;
uniform float uNear, uFar;
uniform bool uEvsm;
uniform vec2 uExponents;    // evsm's [positive, negative]

layout(location = 0) out vec4 outMoments;

vec4 texelMoments(ivec2 texel) {
    ivec2 size = textureSize(uDepth, 0).xy;
    float z = texelFetch(uDepth, ivec3(clamp(texel, ivec2(0), size - 1), uLayer), 0).r;
    float u = momentsDepth(z, uPerspective, uReversed, uNear, uFar);
    return uEvsm ? evsmMoments(u, uExponents) : vsmMoments(u);
}

void main() { outMoments = boxBlur(ivec2(gl_FragCoord.xy), uStep, uRadius); }
