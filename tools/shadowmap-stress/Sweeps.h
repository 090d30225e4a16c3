#pragma once
// What shadowmap-stress sweeps and the bounds its results must hold.
//
// Sweeps (each point is rendered for every light kind listed, variant and depth format; a
// volume light renders no map, so once per point, its format column empty):
//   distance   everything translated 0, 1e3, 1e5, 1e6, 1e7 units from the origin (node
//              translations, as glTF scenes place meshes)
//   distance_skinned  the same offsets with every mesh skinned to a joint that carries its
//              placement (posed on the CPU, as exported characters are)
//   distance_baked  the same offsets baked into the float vertex positions
//   near_far   spot and point lights with near/far forced to 1e-2 ... 1e-7, and an
//              infinite far plane (near = 1e-3 of the farthest scene corner)
//   elevation  light direction 45 deg down to 0.5 deg over the floor (grazing)
//   scale      every length times 1e-4 ... 1e4
//   shimmer    the directional light with four cascades, stable and fitted, each measured
//              for shimmer on an 8-frame pan of the camera one pixel a frame (full run only)
//   special    light inside a closed box, light on a surface, camera at the light,
//              light straight down (parallel to the usual up vector), an alpha-masked
//              fence and its opaque twin
// Depth formats: d16, d24, d32f, and d32f_rz (d32f with "reversed_z": true); none for volume.
// The quick version (CI) renders 96x64 pixels with 512-texel maps: distance and
// distance_skinned 0 and 1e6,
// near/far 1e-2, 1e-7 and infinite, scale 1e-3, 1 and 1e3, the light inside a box and the
// masked fence under the spot, in d24, d32f and d32f_rz.
//
// Bounds (checkBounds; the numbers are percentage points of the evaluation set; "error" is
// judgedError's: against the soft truth for a light with a size, e.g. run with
// --set shadowmap_plugin.light_radius=0.2):
//   finite          no NaN/Inf anywhere: shadow term, depth map texels, light matrices
//   has_map         every light that should cast a shadow has a map (no silent skip), or
//                   for volume its visibility per pixel (map kind "volumes"; a map variant
//                   never reports it)
//   distance        |error(d) - error(0)| <= 0.1 for d = 1e3, 1e5, 1e6, per light kind,
//                   variant and format, in distance and distance_skinned
//   distance_1e7    the same at 1e7 (float spacing 1.0 there)
//   scale           |error(s) - error(1)| <= 0.2 for s in [1e-3, 1e3]
//   scale_extreme   the same at 1e-4 and 1e4
//   inside_box      light inside a closed box: the evaluation set is not empty and every
//                   pixel of it is in shadow (leak = 0), d24, d32f, d32f_rz. d16 is
//                   reported: the apex inside the box's bounds pulls near to far * 1e-4,
//                   where 8 d16 units are ~0.17 world units of offset at the walls
//   near_far_rz     reversed-Z d32f and volume (no near/far of its own: its volumes reach
//                   infinity): error(ratio) - error(1e-2) <= 0.5 down to 1e-7 and with an
//                   infinite far plane
//   grazing         standard / backface at every elevation down to 0.5 deg: error without
//                   edge pixels <= 0.5 (woo is reported: its window-depth midpoint between
//                   a grazing floor's top and where the ray leaves the slab lies within a
//                   texel's depth footprint there)
//   special         camera at the light and light straight down: error without edge
//                   pixels <= 0.5
//   shimmer         stable cascades shimmer no more than fitted ones (per map variant and
//                   format), and fitted ones shimmer at all (the path compared something);
//                   volume (no cascades) shimmers on no more than kVolumeShimmer of the points
//   volume          exact hard shadows: every volume row (but the masked fence) has map
//                   kind "volumes" and its error without edge pixels (binary truth,
//                   whatever the light's size) <= kVolumeErrorNoEdge, tighter than any
//                   bound on a map
//   masked          the masked fence: error and error without edge pixels <= 2 x its
//                   opaque twin's + 0.01; for volume, which cannot test a texture, the
//                   plugin's fallback instead: a standard map erring exactly as the
//                   standard row in the plugin's default depth format
// distance_baked (full sweep only) is reported, not bounded: there the float vertex data
// itself, not a matrix, limits precision.
#include "StressScenes.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace stress {

enum class Axis { Log, LogReversed, Categorical };

struct SweepPoint {
    double value = 0.0;     // the swept number (for plots: where it goes on x)
    std::string label;      // as printed (e.g. "1e6", "inf", "light_inside_box")
    SceneSpec spec;         // light kind, variant and format are filled in per row
    // Light kinds this point is rendered with; empty = the sweep's.
    std::vector<LightKind> lights;
    // > 0: also measure shimmer over this many frames of the one-pixel pan
    // (evaluation/CameraPath.h, truth/Shimmer.h).
    int shimmerFrames = 0;
};

struct Sweep {
    std::string name;   // file names: <name>.png
    std::string title;
    std::string xLabel;
    Axis axis = Axis::Log;
    std::vector<LightKind> lights;
    std::vector<SweepPoint> points;
    std::string note;   // what to read from it (summary.md)
};

// A depth format as the sweep names it and the per-light settings it stands for.
struct FormatSetting {
    std::string name;          // d16, d24, d32f, d32f_rz; "" for a variant without a map
    nlohmann::json settings;   // e.g. {"depth_format":"d32f","reversed_z":true}
};

// Whether `variant` renders a shadow map: every variant but volume (stenciled shadow
// volumes, a visibility per camera pixel), whose depth format, resolution and near/far the
// plugin does not read.
bool rendersMap(const std::string& variant);
// The formats a case of `variant` is rendered in: `formats` for a map, else one without a
// name or settings, so a volume light gives one row per case rather than the same picture
// once per format.
std::vector<FormatSetting> formatsFor(const std::string& variant, const std::vector<FormatSetting>& formats);

// Percentage points: the volume bound's error without edge pixels (checkBounds), and the
// most shimmer a volume may show on the pan; measured in Sweeps.cpp.
inline constexpr double kVolumeErrorNoEdge = 0.01, kVolumeShimmer = 0.01;

std::vector<Sweep> makeSweeps(bool quick);
std::vector<std::string> defaultVariants();
std::vector<FormatSetting> defaultFormats(bool quick);
// Every format the tool knows (for --formats), by name.
std::vector<FormatSetting> knownFormats();
// The name of d32f with reversed_z: "d32f_rz".
std::string reversedZFormat();

// One rendered case and what it measured (errors in percent of the evaluation set).
struct Row {
    std::string sweep, light, variant, format, label;
    double value = 0.0;
    double acne = 0.0, leak = 0.0, error = 0.0, errorNoEdge = 0.0;
    std::size_t evaluated = 0;
    std::size_t nonFiniteShade = 0;   // shadow-term pixels that are NaN/Inf
    std::size_t nonFiniteDepth = 0;   // shadow-map texels that are NaN/Inf
    bool nonFiniteStats = false;      // the plugin reported a non-finite near/far/L
    std::string map;                  // "2d", "cube", "cascades", "volumes" or "none"
    std::string skipReason;           // why no map, if none
    double nearPlane = 0.0, farPlane = 0.0;  // the light's (farPlane < 0: infinite)
    double seconds = 0.0;             // wall time of the row
    double shimmer = -1.0;            // percent of compared points; < 0: not measured
    bool expectMap = true;            // false where losing the shadow is right
    // A light with a size (light_radius, angular_diameter): its errors against the soft
    // truth, the visible fraction of the light (truth::softShadowErrors: error = mean
    // |truth - shade| over the evaluation set, without edge pixels, and over the penumbra
    // alone); empty for a light without a size.
    struct SoftErrors {
        double error = 0.0, errorNoEdge = 0.0, penumbraError = 0.0;
    };
    std::optional<SoftErrors> soft;
};

// The error a bound judges a row by, and what it is called in the bound's lines. A light
// with a size is judged against the soft truth: the binary truth counts every partly lit
// pixel of a true penumbra as wrong, so a right soft shadow would fail every bound. A light
// without a size is judged against the binary truth.
struct JudgedError {
    double error = 0.0, errorNoEdge = 0.0;
    std::string name, nameNoEdge;  // "error", "error_noedge" or "soft_error", "soft_error_noedge"
    bool soft = false;             // against the soft truth
};
JudgedError judgedError(const Row& row);

struct BoundResult {
    std::string name;
    std::string description;
    int checked = 0;                    // comparisons made
    std::vector<std::string> failures;  // one line per failing comparison
    std::string worst;                  // the worst comparison, pass or fail
    bool pass() const { return failures.empty(); }
};

std::vector<BoundResult> checkBounds(const std::vector<Row>& rows);

} // namespace stress
