#include "Sweeps.h"

#include "shadowmap/ShadowSettings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <tuple>

namespace stress {

namespace {

std::string number(double value, const char* format = "%.3f") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// The direction everything is moved along in the distance sweep: all three coordinates
// large (unit length: 0.6^2 + 0.48^2 + 0.64^2 = 1).
const glm::dvec3 kFarDirection(0.6, 0.48, 0.64);

SweepPoint point(double value, std::string label, SceneSpec spec = {}) {
    SweepPoint p;
    p.value = value;
    p.label = std::move(label);
    p.spec = std::move(spec);
    return p;
}

Sweep distanceSweep(bool quick) {
    Sweep sweep{"distance", "Scene translated away from the origin", "distance from the origin",
                Axis::Log, {LightKind::Spot, LightKind::Directional, LightKind::Point}, {}, {}};
    const std::vector<std::pair<double, const char*>> distances =
        quick ? std::vector<std::pair<double, const char*>>{{0.0, "0"}, {1e6, "1e6"}}
              : std::vector<std::pair<double, const char*>>{
                    {0.0, "0"}, {1e3, "1e3"}, {1e5, "1e5"}, {1e6, "1e6"}, {1e7, "1e7"}};
    for (const auto& [d, label] : distances) {
        SceneSpec spec;
        spec.offset = kFarDirection * d;
        sweep.points.push_back(point(d, label, spec));
    }
    sweep.note = "Meshes placed by node translations (double) and the light and camera with them: every "
                 "matrix is composed in double and handed over light- or camera-relative, so the error "
                 "must not move. Bounds: distance (up to 1e6), distance_1e7.";
    return sweep;
}

// The distance sweep's points, each scene changed by `change`, under another name.
Sweep distanceVariant(bool quick, const char* name, const char* title, void (*change)(SceneSpec&), const char* note) {
    Sweep sweep = distanceSweep(quick);
    sweep.name = name;
    sweep.title = title;
    for (SweepPoint& point : sweep.points) change(point.spec);
    sweep.note = note;
    return sweep;
}

// The same distances with the offset baked into float vertex positions: what no double
// matrix can repair (float spacing 0.0625 at 1e6), reported to show where the data, not
// the engine, sets the limit.
Sweep bakedDistanceSweep() {
    return distanceVariant(
        false, "distance_baked", "Scene far from the origin, offset baked into float vertex positions",
        [](SceneSpec& spec) { spec.bakeOffset = true; },
        "Reported, not bounded. The offset is in the float vertex positions themselves (identity "
        "nodes), so the data is quantized where it is stored (spacing 0.0625 at 1e6). The engine "
        "uploads each mesh relative to its bounds' centre (subtracted in double) and folds that "
        "translation into M (SceneGpu::modelMatrix), so the GPU never multiplies 1e6-sized floats: "
        "before that fix a point light's error was 14.7% at 1e3 and 60-90% at 1e6.");
}

// The same distances with every mesh skinned to a joint that carries its placement: the
// posed vertices are computed on the CPU in world space (double) and handed over relative to
// the pose's centre, as for any mesh, so the error must not move either.
Sweep skinnedDistanceSweep(bool quick) {
    return distanceVariant(
        quick, "distance_skinned", "Scene translated away from the origin, every mesh skinned to a joint",
        [](SceneSpec& spec) { spec.skinned = true; },
        "Every mesh skinned to one joint node that carries its placement (inverse bind matrix the identity), "
        "its own node the identity: the vertices are posed on the CPU in double (Deform.h) and stored "
        "relative to the pose's centre, as an exported character is drawn. Bounds: distance (up to 1e6), "
        "distance_1e7, as for distance.");
}

Sweep nearFarSweep(bool quick) {
    Sweep sweep{"near_far", "Light near/far ratio forced (near_plane, far_plane)",
                "near / far", Axis::LogReversed, {LightKind::Spot, LightKind::Point}, {}, {}};
    for (int exponent = 2; exponent <= 7; ++exponent) {
        if (quick && exponent != 2 && exponent != 7) continue;
        SceneSpec spec;
        spec.nearOverFar = std::pow(10.0, -exponent);
        sweep.points.push_back(point(*spec.nearOverFar, "1e-" + std::to_string(exponent), spec));
    }
    SceneSpec infinite;
    infinite.nearOverFar = 1e-3;
    infinite.infiniteFar = true;
    sweep.points.push_back(point(1e-8, "inf", infinite));  // plotted beyond 1e-7
    sweep.note = "near_plane forced to ratio * far_plane (far_plane just beyond the farthest scene corner); "
                 "inf: far_plane \"infinite\", near 1e-3 of that corner. Fixed-point and forward float "
                 "depth store 1 - n/d and run out of steps; reversed-Z d32f stores n/d. Bound: near_far_rz.";
    return sweep;
}

Sweep elevationSweep() {
    Sweep sweep{"elevation", "Light elevation over the floor (grazing at the end)",
                "elevation (degrees)", Axis::LogReversed, {LightKind::Spot, LightKind::Directional}, {}, {}};
    for (double degrees : {45.0, 30.0, 15.0, 5.0, 2.0, 1.0, 0.5}) {
        SceneSpec spec;
        spec.elevationDeg = degrees;
        sweep.points.push_back(point(degrees, number(degrees, "%g"), spec));
    }
    sweep.note = "Spot 14 units from the floor's centre, directional from the same direction. Bound: grazing "
                 "(standard, backface). Woo's window-depth midpoint is reported: at 1 and 0.5 degrees it "
                 "shows acne on the grazing floor (a texel's depth footprint there is longer than the gap to "
                 "the midpoint).";
    return sweep;
}

Sweep scaleSweep(bool quick) {
    Sweep sweep{"scale", "Whole scene scaled", "scale", Axis::Log,
                {LightKind::Spot, LightKind::Directional, LightKind::Point}, {}, {}};
    const std::vector<int> exponents = quick ? std::vector<int>{-3, 0, 3}
                                             : std::vector<int>{-4, -3, -2, -1, 0, 1, 2, 3, 4};
    for (int exponent : exponents) {
        SceneSpec spec;
        spec.scale = std::pow(10.0, exponent);
        sweep.points.push_back(point(spec.scale, exponent == 0 ? "1" : "1e" + std::to_string(exponent), spec));
    }
    sweep.note = "Every length (geometry, placements, camera near/far, forced planes) times the scale. "
                 "Biases are in depth-format units and texels, fits in fractions of their ranges, so nothing "
                 "may move. Bounds: scale ([1e-3, 1e3]), scale_extreme.";
    return sweep;
}

// Four cascades of the directional light, stable and fitted, on the one-pixel pan.
Sweep shimmerSweep() {
    Sweep sweep{"shimmer", "Shimmer of four cascades on a one-pixel pan", "cascades", Axis::Categorical,
                {LightKind::Directional}, {}, {}};
    for (const bool stable : {true, false}) {
        SceneSpec spec;
        spec.shadow = {{"cascades", 4}, {"stable", stable}};
        SweepPoint p = point(stable ? 1.0 : 2.0, stable ? "stable" : "fitted", spec);
        p.shimmerFrames = 8;
        sweep.points.push_back(p);
    }
    sweep.note = "The directional light with four cascades, stable (texel-snapped squares) and fitted to each "
                 "frame, on 8 frames of the camera panning one pixel a frame: shimmer_pct in stress.csv is the "
                 "share of compared surface points whose shadow state changed between frames while the truth "
                 "did not (docs/metrics.md). Bound: shimmer. Not in the quick set: at 96x64 with 512 maps a "
                 "few hundred points are compared and the two settings' shimmer differs by noise (stable woo "
                 "0.092 % against fitted 0.085 %); at 320x240 with 1024 maps stable is 0.019-0.021 % and "
                 "fitted 0.078-0.080 %.";
    return sweep;
}

Sweep specialSweep(bool quick) {
    Sweep sweep{"special", "Special cases", "case", Axis::Categorical, {}, {}, {}};
    const auto add = [&](Layout layout, std::vector<LightKind> lights) {
        SceneSpec spec;
        spec.layout = layout;
        SweepPoint p = point(static_cast<double>(sweep.points.size() + 1), toString(layout), spec);
        p.lights = std::move(lights);
        sweep.points.push_back(p);
    };
    add(Layout::LightInsideBox, {LightKind::Spot, LightKind::Point});
    sweep.note = "light_inside_box: every receiver outside the shell is truly dark (bound inside_box). "
                 "light_on_surface: spot apex on the tower's top, point light on the floor (the floor then "
                 "only casts). camera_at_light: everything visible is lit, any shadow is acne. "
                 "light_straight_down: direction (0,-1,0), the scene turned 3 degrees so no face is edge-on. "
                 "masked_fence: a 6 x 2 fence alone on the floor, one alpha-masked quad (96 x 32 binary-alpha "
                 "texels); opaque_fence: its twin built from one quad per slat and rail, the reference its "
                 "error is read against (the quick set runs the pair with the spot only). Bounds: special, "
                 "masked.";
    if (quick) {
        add(Layout::MaskedFence, {LightKind::Spot});
        add(Layout::OpaqueFence, {LightKind::Spot});
        return sweep;
    }
    add(Layout::LightOnSurface, {LightKind::Spot, LightKind::Point});
    add(Layout::CameraAtLight, {LightKind::Spot});
    add(Layout::LightStraightDown, {LightKind::Spot, LightKind::Directional});
    add(Layout::MaskedFence, {LightKind::Spot, LightKind::Directional, LightKind::Point});
    add(Layout::OpaqueFence, {LightKind::Spot, LightKind::Directional, LightKind::Point});
    return sweep;
}

// Rows of the listed sweeps by (sweep, light, variant, format), then by point label.
using SeriesKey = std::tuple<std::string, std::string, std::string, std::string>;
std::map<SeriesKey, std::map<std::string, const Row*>> series(const std::vector<Row>& rows,
                                                              const std::vector<std::string>& sweeps) {
    std::map<SeriesKey, std::map<std::string, const Row*>> out;
    for (const Row& row : rows)
        if (std::find(sweeps.begin(), sweeps.end(), row.sweep) != sweeps.end())
            out[{row.sweep, row.light, row.variant, row.format}][row.label] = &row;
    return out;
}

std::string describe(const Row& row) {
    return row.sweep + " " + row.label + " " + row.light + "/" + row.variant + (row.format.empty() ? "" : "/" + row.format);
}

bool isVolume(const Row& row) { return !rendersMap(row.variant); }

bool isMaskedFence(const Row& row) { return row.sweep == "special" && row.label == toString(Layout::MaskedFence); }

// |error(label) - error(reference)| <= tolerance for every series of the sweeps and every
// label kept.
void compareWithReference(BoundResult& bound, const std::vector<Row>& rows, const std::vector<std::string>& sweeps,
                          const std::string& reference,
                          const std::function<bool(const Row&)>& keep, double tolerance,
                          bool oneSided = false) {
    double worst = -1.0;
    for (const auto& [key, byLabel] : series(rows, sweeps)) {
        const auto ref = byLabel.find(reference);
        if (ref == byLabel.end()) continue;
        for (const auto& [label, row] : byLabel) {
            if (label == reference || !keep(*row)) continue;
            const JudgedError mine = judgedError(*row), theirs = judgedError(*ref->second);
            const double delta = mine.error - theirs.error;
            const double deviation = oneSided ? delta : std::abs(delta);
            ++bound.checked;
            const std::string line = describe(*row) + ": " + mine.name + " " + number(mine.error) + " vs " +
                                     number(theirs.error) + " at " + reference + " (" +
                                     (delta >= 0 ? "+" : "") + number(delta) + ")";
            if (deviation > worst) {
                worst = deviation;
                bound.worst = line;
            }
            if (deviation > tolerance) bound.failures.push_back(line);
        }
    }
}

// A volume has no texture to test: a volume light among alpha-tested casters gets a standard
// map at its own settings (the plugin warns), so its row must err exactly as the standard row
// of the same case in the plugin's default depth format (the volume row sets none), and show
// a map. Its twin is real volumes, exact: the twin bound would compare a map with them.
void checkVolumeFallback(BoundResult& bound, const std::vector<Row>& rows, const Row& row) {
    const std::string format = shadowmap::toString(shadowmap::ShadowSettings{}.depthFormat);
    const auto standard = std::find_if(rows.begin(), rows.end(), [&](const Row& other) {
        return other.sweep == row.sweep && other.label == row.label && other.light == row.light &&
               other.variant == shadowmap::toString(shadowmap::Variant::Standard) && other.format == format;
    });
    ++bound.checked;
    const bool map = row.map != "volumes" && row.map != "none";
    if (standard == rows.end()) {
        if (!map) bound.failures.push_back(describe(row) + ": map " + row.map + ", not the standard fallback");
        return;
    }
    const std::string line = describe(row) + ": map " + row.map + ", error " + number(row.error, "%.4f") +
                             " vs standard/" + format + " " + number(standard->error, "%.4f");
    if (!map || std::abs(row.error - standard->error) > 1e-4 || std::abs(row.errorNoEdge - standard->errorNoEdge) > 1e-4)
        bound.failures.push_back(line);
}

// A masked caster is as accurate as the same shape built from geometry: for every light,
// variant and format, the masked fence's error (overall and without edge pixels) is at most
// twice its opaque twin's plus 0.01 points (about 5 of the ~45000 evaluated pixels at
// 320x240, so a twin with no error leaves room for rounding at a few texel corners).
// Measured: the masked fence's errors are at or below the twin's in every series (the
// mask's 0.5 iso-line cuts the corners of the opaque texel regions, the twin does not).
BoundResult maskedAgainstTwin(const std::vector<Row>& rows) {
    BoundResult masked{"masked", "masked fence: error and error without edge pixels <= 2 x its opaque twin's + 0.01 "
                       "points; volume: the standard map the plugin gives it there, as the standard row errs",
                       0, {}, {}};
    double worst = -1.0;
    for (const Row& row : rows) {
        if (!isMaskedFence(row)) continue;
        if (isVolume(row)) {
            checkVolumeFallback(masked, rows, row);
            continue;
        }
        const auto twin = std::find_if(rows.begin(), rows.end(), [&](const Row& other) {
            return other.sweep == row.sweep && other.label == toString(Layout::OpaqueFence) &&
                   other.light == row.light && other.variant == row.variant && other.format == row.format;
        });
        if (twin == rows.end()) continue;
        const JudgedError fence = judgedError(row), opaque = judgedError(*twin);
        for (const auto& [what, mine, theirs] : {std::tuple{fence.name, fence.error, opaque.error},
                                                 std::tuple{fence.nameNoEdge, fence.errorNoEdge, opaque.errorNoEdge}}) {
            ++masked.checked;
            const double excess = mine - 2.0 * theirs;
            const std::string line = describe(row) + ": " + what + " " + number(mine) + " vs twin " + number(theirs);
            if (excess > worst) {
                worst = excess;
                masked.worst = line;
            }
            if (excess > 0.01) masked.failures.push_back(line);
        }
    }
    return masked;
}

// Stable cascades keep their texels still while the camera pans, fitted ones move them with
// every frame: per variant and format, stable shimmer <= fitted shimmer, and fitted > 0
// (else the path compared nothing and the bound would hold vacuously). A volume light has
// no cascades and no texels: its shadow is exact at every pixel, so it shimmers on no more
// than kVolumeShimmer of the points, stable or fitted (which it does not read).
BoundResult stableAgainstFitted(const std::vector<Row>& rows) {
    BoundResult bound{"shimmer", "four stable cascades shimmer no more than fitted ones; fitted ones shimmer; volume "
                      "shimmers on <= " + number(kVolumeShimmer, "%g") + " % of the points", 0, {}, {}};
    double worst = -1e300;
    for (const Row& row : rows) {
        if (row.sweep != "shimmer") continue;
        if (isVolume(row)) {
            ++bound.checked;
            const std::string line = describe(row) + ": shimmer " + number(row.shimmer, "%.4f");
            if (row.shimmer > worst) {
                worst = row.shimmer;
                bound.worst = line;
            }
            if (!(row.shimmer >= 0.0 && row.shimmer <= kVolumeShimmer)) bound.failures.push_back(line);
            continue;
        }
        if (row.label != "stable") continue;
        const auto fitted = std::find_if(rows.begin(), rows.end(), [&](const Row& other) {
            return other.sweep == row.sweep && other.label == "fitted" && other.light == row.light &&
                   other.variant == row.variant && other.format == row.format;
        });
        if (fitted == rows.end()) continue;
        ++bound.checked;
        const std::string line = describe(row) + ": shimmer " + number(row.shimmer, "%.4f") + " vs fitted " +
                                 number(fitted->shimmer, "%.4f");
        if (row.shimmer - fitted->shimmer > worst) {
            worst = row.shimmer - fitted->shimmer;
            bound.worst = line;
        }
        if (row.shimmer > fitted->shimmer || !(fitted->shimmer > 0.0)) bound.failures.push_back(line);
    }
    return bound;
}

// Stenciled shadow volumes decide every pixel centre exactly: off the truth's shadow edges
// (where a pixel's one ray and its centre can fall on either side) a volume light errs on
// no pixel, at any distance, scale or near/far. The bound is kVolumeErrorNoEdge points, far
// below what any map variant holds to. Against the binary truth whatever the light's size:
// a volume's shadow is hard, and the soft truth would count every penumbra pixel as its
// error. Alpha-tested casters cast no volume: among them the plugin gives the light a
// standard map (and says so), which the masked bound judges; everywhere else the row must
// be volumes.
BoundResult volumeExact(const std::vector<Row>& rows) {
    BoundResult bound{"volume", "volume: map \"volumes\" and error without edge pixels <= " +
                      number(kVolumeErrorNoEdge, "%g") + " points (masked_fence: the plugin's standard map, bound "
                      "masked)", 0, {}, {}};
    double worst = -1.0;
    for (const Row& row : rows) {
        if (!isVolume(row) || isMaskedFence(row)) continue;
        ++bound.checked;
        const std::string line = describe(row) + ": map " + row.map + ", error_noedge " +
                                 number(row.errorNoEdge, "%.4f") + " (error " + number(row.error, "%.4f") + ")";
        if (row.errorNoEdge > worst) {
            worst = row.errorNoEdge;
            bound.worst = line;
        }
        if (row.map != "volumes" || row.errorNoEdge > kVolumeErrorNoEdge) bound.failures.push_back(line);
    }
    return bound;
}

} // namespace

JudgedError judgedError(const Row& row) {
    if (row.soft) return {row.soft->error, row.soft->errorNoEdge, "soft_error", "soft_error_noedge", true};
    return {row.error, row.errorNoEdge, "error", "error_noedge", false};
}

std::vector<Sweep> makeSweeps(bool quick) {
    if (quick)
        return {distanceSweep(true), skinnedDistanceSweep(true), nearFarSweep(true), scaleSweep(true), specialSweep(true)};
    return {distanceSweep(false), skinnedDistanceSweep(false), bakedDistanceSweep(), nearFarSweep(false),
            elevationSweep(), scaleSweep(false), shimmerSweep(), specialSweep(false)};
}

bool rendersMap(const std::string& variant) { return variant != shadowmap::toString(shadowmap::Variant::Volume); }

std::vector<FormatSetting> formatsFor(const std::string& variant, const std::vector<FormatSetting>& formats) {
    if (rendersMap(variant)) return formats;
    return {FormatSetting{"", nlohmann::json::object()}};
}

std::vector<std::string> defaultVariants() {
    // Every variant the plugin has but "none", which casts no shadow to stress.
    std::vector<std::string> variants = shadowmap::settingKey("variant").choices;
    std::erase(variants, shadowmap::toString(shadowmap::Variant::None));
    return variants;
}

std::string reversedZFormat() {
    // Reversed Z needs float depth (checkLimits): the one format it combines with.
    return shadowmap::toString(shadowmap::DepthFormat::D32F) + std::string("_rz");
}

std::vector<FormatSetting> knownFormats() {
    std::vector<FormatSetting> formats;
    for (const std::string& format : shadowmap::settingKey("depth_format").choices)
        formats.push_back({format, {{"depth_format", format}}});
    const std::string reversible = shadowmap::toString(shadowmap::DepthFormat::D32F);
    formats.push_back({reversedZFormat(), {{"depth_format", reversible}, {"reversed_z", true}}});
    return formats;
}

std::vector<FormatSetting> defaultFormats(bool quick) {
    std::vector<FormatSetting> all = knownFormats();
    if (!quick) return all;
    return {all[1], all[2], all[3]};
}

std::vector<BoundResult> checkBounds(const std::vector<Row>& rows) {
    std::vector<BoundResult> bounds;

    BoundResult finite{"finite", "no NaN/Inf shadow term, depth texel or light matrix anywhere", 0, {}, {}};
    std::size_t worstCount = 0;
    for (const Row& row : rows) {
        ++finite.checked;
        const std::size_t bad = row.nonFiniteShade + row.nonFiniteDepth + (row.nonFiniteStats ? 1 : 0);
        if (bad > 0)
            finite.failures.push_back(describe(row) + ": " + std::to_string(row.nonFiniteShade) +
                                      " shade pixels, " + std::to_string(row.nonFiniteDepth) +
                                      " depth texels" + (row.nonFiniteStats ? ", non-finite matrices" : ""));
        if (bad >= worstCount) {
            worstCount = bad;
            finite.worst = describe(row) + ": " + std::to_string(bad) + " non-finite values";
        }
    }
    bounds.push_back(finite);

    BoundResult hasMap{"has_map", "every light that should cast a shadow has a map, a volume light its visibility "
                       "per pixel (map \"volumes\") or its fallback map", 0, {}, {}};
    for (const Row& row : rows) {
        if (!row.expectMap) continue;
        ++hasMap.checked;
        if (row.map == "none") hasMap.failures.push_back(describe(row) + ": no map (" + row.skipReason + ")");
        else if (!isVolume(row) && row.map == "volumes")
            hasMap.failures.push_back(describe(row) + ": map \"" + row.map + "\" for variant " + row.variant);
    }
    hasMap.worst = hasMap.failures.empty() ? "all have a map" : hasMap.failures.front();
    bounds.push_back(hasMap);

    // Node-placed and skinned meshes alike.
    BoundResult distance{"distance", "|error(d) - error(0)| <= 0.1 points for d = 1e3, 1e5, 1e6 (distance, "
                         "distance_skinned)", 0, {}, {}};
    BoundResult distance7{"distance_1e7", "|error(1e7) - error(0)| <= 0.1 points (distance, distance_skinned)", 0, {}, {}};
    const std::vector<std::string> placements = {"distance", "distance_skinned"};
    compareWithReference(distance, rows, placements, "0", [](const Row& r) { return r.value <= 1e6; }, 0.1);
    compareWithReference(distance7, rows, placements, "0", [](const Row& r) { return r.value > 1e6; }, 0.1);
    bounds.push_back(distance);
    bounds.push_back(distance7);

    BoundResult scale{"scale", "|error(s) - error(1)| <= 0.2 points for s in [1e-3, 1e3]", 0, {}, {}};
    compareWithReference(scale, rows, {"scale"}, "1",
                         [](const Row& r) { return r.value >= 0.99e-3 && r.value <= 1.01e3; }, 0.2);
    bounds.push_back(scale);

    BoundResult scaleExtreme{"scale_extreme", "|error(s) - error(1)| <= 0.2 points for s = 1e-4, 1e4", 0, {}, {}};
    compareWithReference(scaleExtreme, rows, {"scale"}, "1",
                         [](const Row& r) { return r.value < 0.99e-3 || r.value > 1.01e3; }, 0.2);
    bounds.push_back(scaleExtreme);

    BoundResult inside{"inside_box",
                       "light inside a closed box: evaluation set not empty, every pixel of it shadowed (leak 0); "
                       "d16 reported, not bounded",
                       0, {}, {}};
    double worstLeak = -1.0;
    for (const Row& row : rows) {
        if (row.sweep != "special" || row.label != toString(Layout::LightInsideBox) ||
            row.format == shadowmap::toString(shadowmap::DepthFormat::D16))
            continue;
        ++inside.checked;
        const std::string line = describe(row) + ": leak " + number(row.leak, "%.4f") + " of " +
                                 std::to_string(row.evaluated) + " pixels";
        if (row.leak > worstLeak) {
            worstLeak = row.leak;
            inside.worst = line;
        }
        if (row.evaluated == 0 || row.leak > 0.0) inside.failures.push_back(line);
    }
    bounds.push_back(inside);

    // Volumes have no depth range to run out of: held to the same bound as reversed Z.
    BoundResult nearFar{"near_far_rz",
                        "reversed-Z d32f and volume: error(ratio) - error(1e-2) <= 0.5 points down to 1e-7 and an "
                        "infinite far",
                        0, {}, {}};
    compareWithReference(nearFar, rows, {"near_far"}, "1e-2",
                         [](const Row& r) { return r.format == reversedZFormat() || isVolume(r); }, 0.5, true);
    bounds.push_back(nearFar);

    BoundResult grazing{"grazing",
                        "standard, backface at every elevation down to 0.5 deg: error without edge pixels <= 0.5 "
                        "points (woo reported, not bounded)",
                        0, {}, {}};
    double worstGrazing = -1.0;
    for (const Row& row : rows) {
        if (row.sweep != "elevation" || row.variant == shadowmap::toString(shadowmap::Variant::Woo)) continue;
        ++grazing.checked;
        const JudgedError judged = judgedError(row);
        const std::string line = describe(row) + ": " + judged.nameNoEdge + " " + number(judged.errorNoEdge);
        if (judged.errorNoEdge > worstGrazing) {
            worstGrazing = judged.errorNoEdge;
            grazing.worst = line;
        }
        if (judged.errorNoEdge > 0.5) grazing.failures.push_back(line);
    }
    bounds.push_back(grazing);

    BoundResult special{"special", "camera at the light, light straight down: error without edge pixels <= 0.5 points",
                        0, {}, {}};
    double worstSpecial = -1.0;
    for (const Row& row : rows) {
        if (row.sweep != "special" || (row.label != toString(Layout::CameraAtLight) &&
                                       row.label != toString(Layout::LightStraightDown)))
            continue;
        ++special.checked;
        const JudgedError judged = judgedError(row);
        const std::string line = describe(row) + ": " + judged.nameNoEdge + " " + number(judged.errorNoEdge);
        if (judged.errorNoEdge > worstSpecial) {
            worstSpecial = judged.errorNoEdge;
            special.worst = line;
        }
        if (judged.errorNoEdge > 0.5) special.failures.push_back(line);
    }
    bounds.push_back(special);
    bounds.push_back(volumeExact(rows));
    bounds.push_back(maskedAgainstTwin(rows));
    bounds.push_back(stableAgainstFitted(rows));
    return bounds;
}

} // namespace stress
