#pragma once
// Time and error of every shadowed light of one view, as the main job, the bench and the
// stress tool report them: frames rendered with per-pass timing (each pass closed by
// glFinish), then one more frame with every light's shadow mask, compared with the
// ray-traced truth (truth/RayTracedVisibility.h) on the evaluation set of docs/metrics.md.
#include "truth/RayTracedVisibility.h"
#include "truth/ShadowMetrics.h"
#include "truth/Shimmer.h"
#include "truth/SurfaceCapture.h"
#include "truth/TexelMetric.h"

#include "engine/render/Renderer.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace evaluation {

// The percentile of m that LightResult::texelOnScreen reports beside the mean: the tail
// where the map is coarsest on screen, which a mean over mostly well-sampled pixels hides.
inline constexpr double kTexelPercentile = 0.95;

// The on-screen size m of a light's map texels (truth/TexelMetric.h), over the pixels of the
// evaluation set that have one (a layer that covers them, not edge-on to the light).
struct TexelOnScreen {
    double mean = 0.0;
    double p95 = 0.0;       // nearest rank, kTexelPercentile
    std::size_t count = 0;  // pixels counted; 0: no figure (mean and p95 mean nothing)
};
// The figures of a per-pixel m image (truth::texelOnScreenImage) over its finite values: what
// --truth prints, and engine-view's density view beside its picture.
TexelOnScreen summarizeTexelOnScreen(const std::vector<double>& m);

struct LightResult {
    std::string light;        // for people
    int slot = -1;            // the light instance
    engine::ShadowView view;  // what the shadow plugin published for it (settings, map)
    double shadowMs = 0.0;    // median wall time of its shadow passes, over frames they ran
    int framesRendered = 0;   // frames in which its map was rendered (not cached)
    truth::ShadowErrors errors;
    // Against the area truth (lit fraction of each pixel), when the evaluator computes it;
    // evaluated == 0 otherwise. The figure that judges a filtered (PCF) shade.
    truth::ShadowErrors areaErrors;
    // With setNearDistance(d): the errors on the evaluation pixels whose surface point lies
    // within d of the camera; evaluated == 0 otherwise.
    truth::ShadowErrors nearErrors;
    // For a light with a size (ShadowView::lightRadius, angularDiameter): against the soft
    // truth, the share of the light visible from each pixel's point (truth::softShadowErrors,
    // penumbra figures included), whatever the filter; evaluated == 0 for a point light.
    truth::ShadowErrors softErrors;
    TexelOnScreen texelOnScreen;
    // With setKeepTruth(true): the truth the light is scored against, per pixel, top row
    // first (softErrors' visible fraction for a light with a size, else errors' one-ray
    // visibility as 0 or 1), and the evaluation set (1 = scored); empty otherwise, so the
    // bench and the tuner hold no images per light.
    std::vector<float> truth;
    std::vector<std::uint8_t> evaluated;
    std::size_t nonFinitePixels = 0;  // NaN/Inf anywhere in its shade (must stay 0)
};

// One light's shimmer over a camera path (truth/Shimmer.h), pooled over consecutive frames.
struct LightShimmer {
    std::string light;
    int slot = -1;
    truth::ShimmerCount count;
};

struct ViewResult {
    double frameMs = 0.0;  // median over the timed frames
    std::vector<double> frameTimes;  // every timed frame's wall time, ms, in render order
    std::vector<LightResult> lights;
    std::vector<std::uint8_t> image;  // the last timed frame, RGBA8, top row first
};

// Holds the Embree scene (built once) and the surface capture program; the renderer must
// have `scene` set and a GL context must be current.
class ShadowEvaluator {
public:
    ShadowEvaluator(engine::Renderer& renderer, const engine::Scene& scene);

    // Also score every light against the area truth (16 shadow rays per pixel instead of 1).
    void setAreaTruth(bool enabled) { areaTruth_ = enabled; }
    // Also score every light on the pixels within `distance` of the camera (0: not).
    void setNearDistance(double distance) { nearDistance_ = distance; }
    // Keep each light's truth image and evaluation set in its LightResult (engine-render
    // --truth-mask writes them).
    void setKeepTruth(bool enabled) { keepTruth_ = enabled; }

    // Renders `frames` timed frames of `camera` (0: none, errors only), then evaluates every
    // light that has a shadow (variant other than none).
    ViewResult evaluate(const engine::FrameCamera& camera, int frames);

    // Renders the cameras of `path` in turn (the plugin keeps or re-renders maps as it would
    // for a moving viewer) with every shadowed light's mask, and pools each light's shimmer
    // over consecutive frames.
    std::vector<LightShimmer> shimmer(const std::vector<engine::FrameCamera>& path);

    // Whether a light is scored at all: shadowed (its variant is not none) and emitting light
    // (a light of intensity 0 shadows nothing: its mask says lit everywhere, and scoring it
    // reported leaks no one can see).
    bool scored(const engine::ShadowView& view) const;

    // The light `view` was shadowed for, as the truth samples it.
    static truth::LightExtent lightExtent(const engine::ShadowView& view) {
        return {view.lightRadius, view.angularDiameter};
    }

private:
    engine::Renderer& renderer_;
    const engine::Scene& scene_;
    truth::SurfaceCapture capture_;
    truth::RayTracedVisibility visibility_;
    bool areaTruth_ = false;
    double nearDistance_ = 0.0;
    bool keepTruth_ = false;
};

} // namespace evaluation
