#pragma once
// One trial of per-light shadow settings, as shadowmap-bench and shadowmap-tune run it:
// the caller edits lights' extras.shadow (setLightShadow), the trial makes the plugin re-read
// them, renders each view untimed once (llvmpipe compiles shaders at their first draw, new
// maps are allocated), then times `frames` frames per view and compares every shadowed
// light with the ray-traced truth (ShadowEvaluator). Several views pool into one figure per
// light, so a setting is not fitted to one picture.
#include "ShadowEvaluation.h"

#include "engine/render/Frame.h"
#include "engine/render/Renderer.h"
#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace evaluation {

// Sets light `light`'s (an index into scene.lights) extras.shadow to `shadow`'s keys over
// what it had: every key of `owned` is dropped first, then `shadow`'s keys are written, so
// a key the caller owns and leaves out of `shadow` goes back to its default. Keys nobody
// owns (dimming, reversed_z, ...) stay. A malformed extras or extras.shadow (not an object)
// is left alone for the plugin to report.
void setLightShadow(engine::Scene& scene, int light, const nlohmann::json& shadow,
                    const std::vector<std::string>& owned = {});

// The errors of several views as one: each view's acne, leak and error weighted by the
// size of its evaluation set, the penumbra error by the size of its penumbra (the figures
// one big image of all views would give).
truth::ShadowErrors pooledErrors(const std::vector<truth::ShadowErrors>& views);

// The truth a light's settings are ranked by (shadowmap-tune; shadowmap-bench's
// BenchRow::rankedError states the same rule on its rows): for a light with a size the soft
// truth, the visible share of the light, since only it models the penumbra such a light
// casts; for a point light the area truth, which does not count a filter's partial shade as
// error where an edge really crosses the pixel (it needs SettingTrial::setAreaTruth(true)).
enum class RankingTruth { Area, Soft };
RankingTruth rankingTruth(const LightResult& light);
// The light's errors against that truth.
const truth::ShadowErrors& rankedErrors(const LightResult& light);
// How reports name the figure: "soft error" or "area error".
const char* rankedFigure(RankingTruth truth);

struct TrialResult {
    double frameMs = 0.0;             // median over the views' median frame times
    // The tail beside it, over every timed frame of every view (the frames the views'
    // medians come from), nearest rank as tools::percentile: p99 and max, ms.
    double frameP99Ms = 0.0, frameMaxMs = 0.0;
    std::vector<LightResult> lights;  // per shadowed light instance; every error figure (soft
                                      // ones included) pooled over views, shadowMs the
                                      // median over views
};

class SettingTrial {
public:
    // `scene` must outlive the trial and is what the renderer draws; the Embree scene is
    // built once here (settings change no geometry). A GL context must be current.
    SettingTrial(engine::Renderer& renderer, const engine::Scene& scene, std::vector<engine::FrameCamera> views,
                 int frames);

    // Measures the scene's lights with their extras.shadow as they are now. The first call
    // uploads the scene; later calls only make the plugin re-read the settings (geometry
    // stays on the GPU).
    TrialResult measure();

    // Each light's shimmer under the settings of the last measure() (ShadowEvaluator::shimmer).
    std::vector<LightShimmer> shimmer(const std::vector<engine::FrameCamera>& path) { return evaluator_.shimmer(path); }

    // Also score every light against the area truth (ShadowEvaluator::setAreaTruth).
    void setAreaTruth(bool enabled) { evaluator_.setAreaTruth(enabled); }
    // Also score every light near the camera (ShadowEvaluator::setNearDistance).
    void setNearDistance(double distance) { evaluator_.setNearDistance(distance); }

    int renders() const { return renders_; }  // measure() calls so far

private:
    engine::Renderer& renderer_;
    const engine::Scene& scene_;
    std::vector<engine::FrameCamera> views_;
    int frames_;
    ShadowEvaluator evaluator_;
    int renders_ = 0;
};

} // namespace evaluation
