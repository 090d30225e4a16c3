#pragma once
// One measured point of the sweep: one light of one scene under one shadow setting. The
// row of results.csv, and what the summary and the plot are made of.
#include "engine/util/FormatNumber.h"
#include "shadowmap/ShadowSettings.h"

#include <optional>
#include <string>

namespace shadowmap_bench {

// " taps32" for a set value, "" for an unset one: labels name only what the sweep set.
template <typename T>
std::string labelPart(const char* prefix, const std::optional<T>& value) {
    return value ? prefix + engine::formatNumber(*value) : std::string();
}

// Whether `variant` renders a shadow map: every variant but volume (stenciled shadow
// volumes: a visibility per camera pixel, exact and hard), which reads none of a map's
// settings, so the sweep measures it once per light and size step.
inline bool rendersMap(const std::string& variant) {
    return variant != shadowmap::toString(shadowmap::Variant::Volume);
}

struct ShadowSetting {
    std::string variant;  // standard | woo | backface | volume
    // A map's (rendersMap(variant)); a volume setting leaves them 0 and "" (results.csv
    // leaves their columns empty), and the light keeps its scene's or the config's values,
    // which the plugin reads only where it gives a volume light a standard map instead
    // (among alpha-tested casters: a volume cannot test a texture).
    int resolution = 0;   // texels per side
    std::string depthFormat;  // d16 | d24 | d32f
    std::string filter;       // nearest | pcf | pcss | vsm | evsm
    // The optional axes (SweepAxes.h); unset: the key is not written, so the light keeps the
    // value its scene or the engine config gives it. (Initialised, so that the four-field
    // brace lists the sweep builds settings with need not spell them out.)
    std::optional<double> lightRadius = std::nullopt;      // spot and point lights, world units
    std::optional<double> angularDiameter = std::nullopt;  // directional lights, radians
    std::optional<double> filterRadius = std::nullopt;     // pcf, vsm, evsm: texels (vsm, evsm: the moments' blur)
    std::optional<int> filterTaps = std::nullopt;          // pcss, and pcf with a filter radius
    std::optional<double> bleedReduction = std::nullopt;   // vsm, evsm only
    std::optional<double> normalOffset = std::nullopt;     // texels
    // Directional lights only (spot and point lights keep their own): the projection, the
    // cascade count (shadowmap::kAutoCascades for "auto"), and whether cascades are stable.
    std::optional<shadowmap::Projection> projection = std::nullopt;
    std::optional<int> cascades = std::nullopt;
    std::optional<bool> stable = std::nullopt;
    // Set by markDirectionalRepeats (SweepAxes.h): this setting differs from an earlier one of
    // its scene only in the directional-only axes, so a spot or point light gets exactly what
    // it got there and its row is not written again.
    bool directionalRepeat = false;

    bool operator==(const ShadowSetting&) const = default;

    // "woo 2048 d24 pcf", then what the sweep set: "lr0.1 ad0.05" (light radius, angular
    // diameter), "fr2" (filter radius), "taps32", "br0.2" (bleed reduction), "no0.25"
    // (normal offset), "uniform" or "lispsm" (projection), "c2" or "cauto" (cascades),
    // "stable" or "unstable", e.g. "standard 1024 d24 pcss lr0.1 ad0.05 taps32 no0.25",
    // "standard 1024 d24 vsm fr2 br0.2" or "woo 2048 d24 pcf lispsm c2"; a volume setting
    // "volume" (and its size step: "volume lr0.1").
    std::string label() const { return labelWithSize(sizeLabel()); }

    // The size step's part of the label: " lr0.1 ad0.05", "" without one.
    std::string sizeLabel() const { return labelPart(" lr", lightRadius) + labelPart(" ad", angularDiameter); }

    // The label with `size` (a light size part) where the sizes stand.
    std::string labelWithSize(const std::string& size) const {
        // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + temporary.
        std::string map;
        if (rendersMap(variant)) map.append(" ").append(std::to_string(resolution)).append(" ").append(depthFormat)
                                     .append(" ").append(filter);
        return variant + map + size +
               labelPart(" fr", filterRadius) + labelPart(" taps", filterTaps) + labelPart(" br", bleedReduction) +
               labelPart(" no", normalOffset) +
               (projection ? std::string(" ") + shadowmap::toString(*projection) : std::string()) +
               (cascades ? " c" + cascadesText(*cascades) : std::string()) +
               (stable ? (*stable ? " stable" : " unstable") : std::string());
    }

    // A cascade count as the settings write it: "auto" for kAutoCascades, else the count.
    static std::string cascadesText(int count) {
        return count == shadowmap::kAutoCascades ? "auto" : std::to_string(count);
    }
};

struct BenchRow {
    std::string scene;  // the file's stem, e.g. "showcase"
    std::string light;
    // The sweep's setting without its size step (lightRadius, angularDiameter unset): a row
    // holds the one size its light had, lightSize, which results.csv keeps and --merge reads.
    ShadowSetting setting;
    // The light's size as the row applied it, from the size step or the scene: its radius
    // (spot, point; world units) or angular diameter (directional; radians); 0: none.
    double lightSize = 0.0;
    double shadowMs = 0.0;  // median wall time of the light's shadow passes
    double frameMs = 0.0;   // median wall time of the whole frame (all lights)
    // The tail beside it: p99 and max over the same timed frames (every view's), nearest
    // rank (tools::percentile; under 100 frames the p99 is the max).
    double frameP99Ms = 0.0, frameMaxMs = 0.0;
    // Percent of the evaluation set (docs/metrics.md), against the one-ray-per-pixel truth.
    double acne = 0.0, leak = 0.0, error = 0.0, errorNoEdge = 0.0;
    // The same against the area truth (lit fraction of each pixel's footprint): the figure
    // a point light's settings are ranked by, since it does not count a filter's partial
    // shade at an edge as error when the edge really crosses the pixel.
    double areaAcne = 0.0, areaLeak = 0.0, areaError = 0.0;
    // With --shimmer: percent of the compared surface points whose shadow state changed
    // between consecutive frames of the camera path (truth/Shimmer.h); none without.
    std::optional<double> shimmer;
    // With --near D: the error and the error off edges on pixels within D of the camera.
    std::optional<double> nearError, nearErrorNoEdge;
    // A light with a size (lightSize > 0) only: percent mean |shade - truth| against the soft
    // truth, the visible fraction of the light (docs/soft-shadows.md), over the evaluation
    // set, off edges, and over the penumbra (pixels where truth or shade is strictly between
    // 0 and 1; 0 when there is none).
    std::optional<double> softError, softErrorNoEdge, penumbraError;
    // The on-screen size m of the light's map texels in pixels (docs/metrics.md, "texel on
    // screen"): mean and 95th percentile over the evaluation set; none where no pixel has one.
    std::optional<double> texelMean, texelP95;

    // The error settings are ranked by (summary, Pareto front, plot): against the truth that
    // models the light, the soft truth for a sized light, else the area truth.
    double rankedError() const { return softError.value_or(areaError); }

    // The setting's label with the light's own size ("size0.1") where it has one.
    std::string label() const {
        return setting.labelWithSize(lightSize > 0.0 ? labelPart(" size", std::optional<double>(lightSize)) : "");
    }
};

} // namespace shadowmap_bench
