#pragma once
// Light-space perspective shadow maps (Wimmer, Scherzer, Purgathofer, "Light Space
// Perspective Shadow Maps", EGSR 2004) for a directional light's single map. No GL.
//
// A uniform (orthographic) map spends its texels evenly over the ground, so the ground near
// the camera, which covers many pixels, gets as few texels as the far ground. LiSPSM puts
// a perspective projection between the light's view and the map: it looks along the
// camera's view direction projected onto the plane perpendicular to the light (the warp
// axis), from a centre C a distance n before the body B (what the map must hold: the
// visible receivers inside the camera's frustum, extruded toward the light to the casters
// over them), and the map is then an orthographic view of B in that perspective's space.
// Its frustum's axis is perpendicular to the light, so light rays stay parallel through the
// warp: the depth comparison and the ortho view along them stay as for a uniform map, and
// near the camera texels shrink by up to f/n along the warp axis.
//
// n trades near against far texels: small n magnifies the near end most; n -> infinity is
// the uniform map. n_opt = (z_n + sqrt(z_f z_n)) / sin(gamma), with z_n = near / sin(gamma)
// and z_f = z_n + d sin(gamma) (near: the body's nearest view depth; d: its extent along the
// warp axis; gamma: the angle between the view and light directions), as in Wimmer's
// reference implementation and osgShadow's LispSM: it makes the texel size's error equal at
// the body's near and far ends. lispsm_n_scale multiplies it (the documented override).
//
// As the view turns toward the light's axis the warp axis loses its meaning (at gamma = 0
// any axis perpendicular to the light is as good) and the map must become uniform: the warp
// is weighted by w(gamma), 1 from kLispsmFullWarpAngle up, falling smoothly to 0 at
// kLispsmUniformAngle and below, with n = n_opt / w (1/n, the warp's strength, goes to 0 with
// w), so the map changes continuously with the view.
//
// LightView's L is then a rigid frame at C: x across the warp, y the warp axis, z toward
// the light; its projection P = O * W (W the perspective along y, O the orthographic fit of
// the warped body), so texgen S * P * L^-1 stays the composition Texgen.h describes, with a
// q (the distance along the warp axis) that is no longer 1.
#include "math/LightFrustum.h"

#include <span>

namespace shadowmap {

// Between these angles (view direction to light axis, radians) the warp fades from full to
// none. osgShadow's LispSM switches to uniform below 2 degrees at once; a hard switch jumps
// the texels of the whole map when a camera crosses it, so the warp fades over 2..10 degrees.
inline constexpr double kLispsmUniformAngle = 0.0349065850398866;  // 2 degrees
inline constexpr double kLispsmFullWarpAngle = 0.174532925199433;  // 10 degrees

// w(gamma): 0 at and below kLispsmUniformAngle, 1 at and above kLispsmFullWarpAngle, a
// smoothstep between; sinGamma in [0, 1].
double lispsmWarpWeight(double sinGamma);

// n_opt of the reference implementation (see above); nearDepth > 0, bodyDepth >= 0,
// sinGamma in (0, 1].
double lispsmOptimalN(double nearDepth, double bodyDepth, double sinGamma);

// The camera a warp is fitted for.
struct WarpEye {
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit view direction (V's -Z)
    double nearDepth = 1.0;                 // view depth of the body's nearest point, > 0
};

// What the fit chose, for tests and --stats.
struct LispsmFit {
    double sinGamma = 0.0;
    double weight = 0.0;  // lispsmWarpWeight(sinGamma): 0 uniform
    double n = 0.0;       // the perspective's near distance (infinity when uniform)
    double bodyDepth = 0.0;  // d: the body's extent along the warp axis
};

// The light's map for `direction` (unit, the way its light travels) holding the convex hull
// of `body` (the vertices of the visible receivers cut by the camera's frustum: the hull, not
// a box around it, or the near end would be as wide as the far one and the warp would gain
// nothing across it) and the casters over it. nScale multiplies n_opt (lispsm_n_scale; > 0).
// An empty body gives an empty view.
LightView fitLispsm(const glm::dvec3& direction, const WarpEye& eye, std::span<const glm::dvec3> body,
                    std::span<const engine::Aabb> casters, const FrustumFitOptions& options, double nScale,
                    LispsmFit* chosen = nullptr);

}  // namespace shadowmap
