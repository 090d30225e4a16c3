// Filterable shadow maps (vsm, evsm; technique/lookup/MomentsLookup.h): the depth their
// moments are taken of, EVSM's warp and Chebyshev's bound. Shared by the passes that make the
// moments from the depth map (moments_from_depth.frag) and by the lit pass's lookups
// (vsm.glsl, evsm.glsl), so both read a depth the same way.

// The depth u in [0, 1], growing away from the light and linear in the distance, of window
// depth z. Moments of a window depth would not do: a perspective map's depth crowds toward 1
// (d24 at 10 m of a 0.1 m near plane: 0.99), where E[z^2] - E[z]^2 cancels every digit of a
// float. Orthographic maps (directional lights) are linear already; perspective ones (spot,
// cube faces) give the distance d from near as a fraction of far - near:
// u = (d - n) / (f - n) = n z / (f - z (f - n)), reversed n (1 - z) / (z (f - n) + n). The
// forward denominator cancels toward n as z nears 1, losing about log2(f / n) bits, as many
// as the stored z's own spacing there already lost (tests/shadowmap/gl/MomentsPassTest.cpp
// bounds it).
// near, far: the layer's planes (perspective only; far finite, as the settings require).
float momentsDepth(float z, bool perspective, bool reversed, float near, float far) {
    if (!perspective) return reversed ? 1.0 - z : z;
    float range = far - near;
    return reversed ? near * (1.0 - z) / (z * range + near) : near * z / (far - z * range);
}

// EVSM's warps of u: e^(c+ x) and -e^(-c- x) with x = 2u - 1 in [-1, 1] (Lauritzen and
// McCool, "Layered Variance Shadow Maps", 2008): a positive and a negative exponential, each
// bounding the shade, so overlapping occluders bleed far less than with u itself.
vec2 evsmWarp(float u, vec2 exponents) {
    float x = 2.0 * u - 1.0;
    return vec2(exp(exponents.x * x), -exp(-exponents.y * x));
}

// The moments a texel of depth u holds: VSM (u, u^2), EVSM (p, p^2, n, n^2) of its warps.
vec4 vsmMoments(float u) { return vec4(u, u * u, 0.0, 0.0); }
vec4 evsmMoments(float u, vec2 exponents) {
    vec2 warped = evsmWarp(u, exponents);
    return vec4(warped.x, warped.x * warped.x, warped.y, warped.y * warped.y);
}

// The smallest variance the bound is given, relative to the depth's square: E[u^2] - E[u]^2
// of float moments is exact to a few units of u^2's last place (2^-24 relative; a blur's sum
// adds a few more), so 2^-20 u^2 keeps rounding from reading as variance: a receiver on its
// own surface (t = mean) stays lit, and a texel whose variance rounds to 0 does not divide by 0.
const float kMomentsMinRelativeVariance = 1.0 / 1048576.0;

// Chebyshev's one-sided bound on the share of the filter region not in front of the receiver
// at depth t, given the region's mean and mean square: 1 where t is not behind the mean, else
// variance / (variance + (t - mean)^2).
float chebyshevUpperBound(vec2 moments, float t) {
    float variance = max(moments.y - moments.x * moments.x, kMomentsMinRelativeVariance * t * t);
    float d = t - moments.x;
    return t <= moments.x ? 1.0 : variance / (variance + d * d);
}

// Light-bleeding reduction (Lauritzen, GPU Gems 3, ch. 8): where occluders overlap the bound
// stays above 0 in the umbra of the nearer; cutting off its lowest `amount` and stretching
// the rest over [0, 1] darkens that, at the price of penumbrae that shrink by as much.
float reduceBleeding(float p, float amount) { return clamp((p - amount) / (1.0 - amount), 0.0, 1.0); }
