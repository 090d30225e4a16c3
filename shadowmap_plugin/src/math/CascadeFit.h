#pragma once
// Cascaded shadow maps for a directional light: the camera's view depth range where visible
// receivers are is cut into 1-4 slices by the practical split scheme, and each slice gets its
// own orthographic light view (one layer of the light's array map) fitted to the receivers in
// it and the casters that can shadow them. No GL: the plugin turns the views into passes.
//
// Splits (practical scheme, Zhang et al. "Parallel-split shadow maps", 2006): over the view
// depth range [n, f], split i of N is
//   d_i = lambda * n * (f/n)^(i/N) + (1 - lambda) * (n + (f - n) * i/N),
// lambda = 1 the logarithmic split (equal texel-to-pixel ratio on every slice), 0 the uniform.
//
// Fitted (not stable): each cascade's x/y box is the slice's corners in the light frame,
// intersected with the box of the visible receivers; its depth runs from the farthest
// receiver under that box to the nearest-to-the-light caster over it (as fitDirectionalLight).
//
// Stable: each cascade is a square of fixed size around the slice's bounding sphere (the
// side does not turn with the camera), its centre snapped to whole texels of a light frame
// anchored at the scene's centre, its depth the whole scene's range along the light: a
// camera that moves moves the map only in texel steps, so edges do not crawl. The sphere's
// radius is rounded up to a power of 2^(1/8) so that small changes of the split distances
// keep it. The cost: a square around a sphere holds the slice with spare texels, up to
// about twice the texel size of the fitted box.
#include "math/LightFrustum.h"
#include "shadowmap/ShadowLimits.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace shadowmap {

// count + 1 distances: [0] = nearDepth, [count] = farDepth. lambda in [0, 1].
std::vector<double> cascadeSplits(double nearDepth, double farDepth, int count, double lambda);

// The camera a set of cascades is fitted for (engine::FrameCamera's V and P_eye).
struct CascadeCamera {
    glm::dmat4 eyeToWorld{1.0};  // V
    glm::dmat4 projection{1.0};  // P_eye (perspective or orthographic, finite or infinite far)
};

struct CascadeOptions {
    int count = 1;         // 1..kMaxCascades
    double lambda = 0.5;   // practical split weight
    // cascade_blend: a fitted (not stable) cascade but the last also covers this fraction of
    // its depth range past its far split, where the lookup fades into the next one.
    double blend = 0.0;
    bool stable = false;
    // shadow_distance: no map reaches past this view depth; 0: every visible receiver.
    double maxDistance = 0.0;
    int resolution = kDefaultResolution;  // texels per side of each cascade's map (stable snapping)
    FrustumFitOptions fit;  // margins and reversed Z
};

struct CascadeViews {
    std::vector<LightView> cascades;  // count views; cascades[i].empty: nothing to shadow there
    std::vector<double> splits;       // count + 1 view depths (distance along the camera's -Z)
    bool valid = false;
    std::string invalidReason;
    bool empty = true;  // no visible receiver: no map this frame
};

// The view depth range [near, far] (distance along the camera's -Z) over which the visible
// receivers' boxes lie, clamped to the camera's own near and far planes. False when none do.
bool receiverDepthRange(const CascadeCamera& camera, const std::vector<engine::Aabb>& receivers,
                        double& nearDepth, double& farDepth);

// Whether a directional light's map(s) are slices of the camera's view (fitDirectionalCascades)
// rather than one map fitted to every visible receiver (fitDirectionalLight): with several
// cascades, or with a shadow distance (shadow_distance > 0), which only a slice can end at.
inline bool directionalMapIsSliced(int cascadeCount, double shadowDistance) {
    return cascadeCount > 1 || shadowDistance > 0.0;
}

// receiverDepthRange, ending at options.maxDistance where one is set: the view depths the
// cascades slice. False when no visible receiver lies nearer than that.
bool shadowedDepthRange(const CascadeCamera& camera, const std::vector<engine::Aabb>& receivers,
                        const CascadeOptions& options, double& nearDepth, double& farDepth);

// The eight world-space corners of the camera's frustum between view depths d0 and d1
// (d0 corners first, in the order (-x,-y), (+x,-y), (-x,+y), (+x,+y)).
std::vector<glm::dvec3> frustumSliceCorners(const CascadeCamera& camera, double d0, double d1);

// The far view depth cascade `cascade` covers: its far split, or with a blend band (fitted
// cascades but the last) that split plus the band, where the lookup fades into the next.
double cascadeSliceFar(const std::vector<double>& splits, int cascade, const CascadeOptions& options);

// Rounds a stable cascade's bounding radius up to the next power of 2^(1/8).
double quantizedRadius(double radius);
// The nearest whole-texel position to `value` for texels of `texel` width.
double snapToTexel(double value, double texel);

// sceneBounds: every receiver and caster of the scene (visible or not), the anchor and depth
// range of stable cascades, so that neither depends on the camera.
CascadeViews fitDirectionalCascades(const engine::LightInstance& instance, const engine::Light& light,
                                    const ShadowBounds& bounds, const engine::Aabb& sceneBounds,
                                    const CascadeCamera& camera, const CascadeOptions& options);

// What `cascades: auto` weighs, per count 1..kMaxCascades (index 0 unused; infinity where a
// count gives no map): the texel size of the nearest non-empty map (the single fitted map for
// 1) over the size of a pixel at the nearest visible receiver, and the maps' texel sizes
// averaged over the view depth as pixels see it (geometric mean, each slice weighted by its
// share of log depth; of depth for an orthographic camera).
struct CascadeNeed {
    double texelsPerPixel[kMaxCascades + 1] = {};
    double meanTexel[kMaxCascades + 1] = {};  // world units
};
CascadeNeed cascadeNeed(const engine::LightInstance& instance, const engine::Light& light, const ShadowBounds& bounds,
                        const engine::Aabb& sceneBounds, const CascadeCamera& camera, const CascadeOptions& options,
                        int viewportHeight);

// The count `cascades: auto` chooses from `need`: starting from one map, it adds a cascade
// while the nearest map's texel is larger than a pixel there and the next cascade shrinks the
// mean texel by at least kAddGain; `previous` (the count chosen last frame, 0: none) keeps a
// cascade in use while its gain stays at kKeepGain, so a slowly moving view does not flip the
// count (a new count re-renders every layer).
//
// Why the mean texel and these numbers (engine-render --truth, 640x360, 2048 maps, stable
// cascades, standard, d24, pcf; error / error off shadow edges, %). On the showcase two
// cascades are worse than one (0.063 -> 0.121 % at 1280x720): the near slice's texels shrink
// (the nearest by 1.26-1.50x, depending on the aspect ratio) but the far slice's square
// around its sphere has texels twice the single map's; the mean gain is 0.90-0.98 at every
// size and resolution tried. On the outdoor scene (tools/scripts/make_outdoor.py) with the
// camera's near plane at 20 m, 5 m and 0.1 m, the mean gains of 1 -> 2 -> 3 -> 4 are
// 3.62 / 1.28 / 1.15, 4.76 / 1.39 / 1.18 and 7.86 / 1.54 / 1.23, and the errors
// 0.526 -> 0.203 -> 0.163 -> 0.152, 3.393 -> 0.803 -> 0.524 -> 0.435 and
// 4.146 -> 0.597 -> 0.378 -> 0.305 (off edges 0.162 -> 0.045 -> 0.048 -> 0.058,
// 1.658 -> 0.157 -> 0.083 -> 0.085, 2.783 -> 0.139 -> 0.065 -> 0.044). A gain of 1.35 adds
// the cascades that paid off edges (1.39, 1.54) and not the even trade (1.28) nor a fourth
// depth pass (at most 1.23, for 0.02 points).
inline constexpr double kAddGain = 1.35, kKeepGain = 1.3;
// A map whose nearest texel is no larger than a pixel there needs no finer slice.
inline constexpr double kEnoughTexelsPerPixel = 1.0;
int autoCascadeCount(const CascadeNeed& need, int previous);

}  // namespace shadowmap
