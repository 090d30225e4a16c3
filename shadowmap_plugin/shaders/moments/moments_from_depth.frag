// The first moments pass of a map layer (plugin/MomentsRenderer.h): each texel's moments
// (moments.glsl) of the depth map's texels along uStep, averaged with the box weights of the
// blur's radius; with radius 0, the texel's own. The depth map is read through a 2D-array
// view (a 2D map as one layer, a cube's faces as six), texel by texel, clamped at the edges.
layout(binding = 0) uniform sampler2DArray uDepth;
uniform int uLayer;
uniform ivec2 uStep;        // (1, 0): along s; the second pass (moments_blur.frag) goes along t
uniform float uRadius;      // texels each side; the texel past floor(radius) weighs its fraction
uniform float uNear, uFar;
uniform vec2 uExponents;    // evsm's [positive, negative]
// Each program is built for one kind of layer (MomentsRenderer.cpp defines these 0 or 1):
// constants fold the other kinds' code away, which llvmpipe would otherwise run on every
// texel (a uniform bool per kind cost 2x per tap).
const bool kPerspective = MOMENTS_PERSPECTIVE != 0;  // a spot light's map, a cube face
const bool kReversed = MOMENTS_REVERSED != 0;
const bool kEvsm = MOMENTS_EVSM != 0;

layout(location = 0) out vec4 outMoments;

vec4 texelMoments(ivec2 texel) {
    ivec2 size = textureSize(uDepth, 0).xy;
    float z = texelFetch(uDepth, ivec3(clamp(texel, ivec2(0), size - 1), uLayer), 0).r;
    float u = momentsDepth(z, kPerspective, kReversed, uNear, uFar);
    return kEvsm ? evsmMoments(u, uExponents) : vsmMoments(u);
}

void main() { outMoments = boxBlur(ivec2(gl_FragCoord.xy), uStep, uRadius); }
