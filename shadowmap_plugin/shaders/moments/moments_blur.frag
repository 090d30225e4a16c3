// The second moments pass of a map layer (plugin/MomentsRenderer.h): the first pass's
// moments, blurred along uStep with the same box weights (moments_from_depth.frag).
layout(binding = 0) uniform sampler2D uMoments;
uniform ivec2 uStep;
uniform float uRadius;

layout(location = 0) out vec4 outMoments;

vec4 texelMoments(ivec2 texel) {
    ivec2 size = textureSize(uMoments, 0);
    return texelFetch(uMoments, clamp(texel, ivec2(0), size - 1), 0);
}

void main() { outMoments = boxBlur(ivec2(gl_FragCoord.xy), uStep, uRadius); }
