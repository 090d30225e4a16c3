// The box blur both moments passes apply (moments_from_depth.frag, moments_blur.frag), each
// along one axis, so two passes give a square of side 2 radius + 1: the sum of each one's
// texelMoments(texel) within `radius` texels of `texel` along `step`, the texel just past
// floor(radius) weighted by its fraction (so the blur grows smoothly with the setting), over
// the weights' sum. Each pass defines texelMoments before this file.
vec4 texelMoments(ivec2 texel);

vec4 boxBlur(ivec2 texel, ivec2 step, float radius) {
    int whole = int(floor(radius));
    float fraction = radius - float(whole);
    vec4 sum = vec4(0.0);
    for (int i = -whole; i <= whole; ++i) sum += texelMoments(texel + i * step);
    if (fraction > 0.0)
        sum += fraction * (texelMoments(texel - (whole + 1) * step) + texelMoments(texel + (whole + 1) * step));
    return sum / (float(2 * whole + 1) + 2.0 * fraction);
}
