#pragma once
// One measured point of the sweep: one light of one scene under one shadow setting. The
// row of results.csv, and what the summary and the plot are made of.
#include <optional>
#include <string>

namespace shadowmap_bench {

struct ShadowSetting {
    std::string variant;  // standard | woo | backface
    int resolution = 0;   // texels per side
    std::string depthFormat;  // d16 | d24 | d32f
    std::string filter;       // nearest | pcf

    // "woo 2048 d24 pcf": how the progress line, the summary and the plot name it.
    std::string label() const {
        return variant + " " + std::to_string(resolution) + " " + depthFormat + " " + filter;
    }
};

struct BenchRow {
    std::string scene;  // the scene file's stem, e.g. "showcase"
    std::string light;
    ShadowSetting setting;
    double shadowMs = 0.0;  // median wall time of the light's shadow passes
    double frameMs = 0.0;   // median wall time of the whole frame (all lights)
    // Percent of the evaluation set (docs/metrics.md), against the one-ray-per-pixel truth.
    double acne = 0.0, leak = 0.0, error = 0.0, errorNoEdge = 0.0;
    // The same against the area truth (lit fraction of each pixel's footprint): the figure
    // settings are ranked by, since it does not count a filter's partial shade at an edge as
    // error when the edge really crosses the pixel.
    double areaAcne = 0.0, areaLeak = 0.0, areaError = 0.0;
    // With --shimmer: percent of the compared surface points whose shadow state changed
    // between consecutive frames of the camera path (truth/Shimmer.h); none without.
    std::optional<double> shimmer;
    // With --near D: the error and the error off edges on pixels within D of the camera.
    std::optional<double> nearError, nearErrorNoEdge;
};

} // namespace shadowmap_bench
