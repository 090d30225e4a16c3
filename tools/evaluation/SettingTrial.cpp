#include "SettingTrial.h"

#include "Median.h"

#include <map>

namespace evaluation {

void setLightShadow(engine::Scene& scene, int light, const nlohmann::json& shadow, const std::vector<std::string>& owned) {
    nlohmann::json& extras = scene.lights.at(light).extras;
    if (extras.is_null()) extras = nlohmann::json::object();
    if (!extras.is_object()) return;
    nlohmann::json& current = extras["shadow"];
    if (current.is_null()) current = nlohmann::json::object();
    if (!current.is_object()) return;
    for (const std::string& key : owned) current.erase(key);
    for (const auto& [key, value] : shadow.items()) current[key] = value;
}

truth::ShadowErrors pooledErrors(const std::vector<truth::ShadowErrors>& views) {
    truth::ShadowErrors pooled;
    for (const truth::ShadowErrors& view : views) {
        const double n = static_cast<double>(view.evaluated), m = static_cast<double>(view.evaluatedNoEdge);
        pooled.acne += view.acne * n;
        pooled.leak += view.leak * n;
        pooled.acneNoEdge += view.acneNoEdge * m;
        pooled.leakNoEdge += view.leakNoEdge * m;
        pooled.penumbraError += view.penumbraError * static_cast<double>(view.evaluatedPenumbra);
        pooled.evaluated += view.evaluated;
        pooled.evaluatedNoEdge += view.evaluatedNoEdge;
        pooled.evaluatedPenumbra += view.evaluatedPenumbra;
    }
    if (pooled.evaluated > 0) {
        pooled.acne /= static_cast<double>(pooled.evaluated);
        pooled.leak /= static_cast<double>(pooled.evaluated);
    }
    if (pooled.evaluatedNoEdge > 0) {
        pooled.acneNoEdge /= static_cast<double>(pooled.evaluatedNoEdge);
        pooled.leakNoEdge /= static_cast<double>(pooled.evaluatedNoEdge);
    }
    if (pooled.evaluatedPenumbra > 0) pooled.penumbraError /= static_cast<double>(pooled.evaluatedPenumbra);
    pooled.error = pooled.acne + pooled.leak;
    pooled.errorNoEdge = pooled.acneNoEdge + pooled.leakNoEdge;
    return pooled;
}

RankingTruth rankingTruth(const LightResult& light) {
    return ShadowEvaluator::lightExtent(light.view).isPoint() ? RankingTruth::Area : RankingTruth::Soft;
}

const truth::ShadowErrors& rankedErrors(const LightResult& light) {
    return rankingTruth(light) == RankingTruth::Soft ? light.softErrors : light.areaErrors;
}

const char* rankedFigure(RankingTruth truth) { return truth == RankingTruth::Soft ? "soft error" : "area error"; }

SettingTrial::SettingTrial(engine::Renderer& renderer, const engine::Scene& scene,
                           std::vector<engine::FrameCamera> views, int frames)
    : renderer_(renderer), scene_(scene), views_(std::move(views)), frames_(frames), evaluator_(renderer, scene) {}

TrialResult SettingTrial::measure() {
    if (renders_++ == 0) renderer_.setScene(scene_);
    else renderer_.reloadSettings();

    std::vector<double> frameMs;
    std::vector<double> allFrames;  // every view's timed frames, for the tail
    std::map<int, std::vector<LightResult>> bySlot;  // per light instance, one per view
    for (const engine::FrameCamera& camera : views_) {
        // Untimed until nothing new compiles (llvmpipe compiles at first draw; new maps are
        // allocated): four frames past the first are more than the two warm-up ever needs.
        engine::FrameRequest warmup;
        warmup.camera = camera;
        renderer_.warmUp(warmup, 1, 5);
        ViewResult view = evaluator_.evaluate(camera, frames_);
        frameMs.push_back(view.frameMs);
        allFrames.insert(allFrames.end(), view.frameTimes.begin(), view.frameTimes.end());
        for (LightResult& light : view.lights) bySlot[light.slot].push_back(std::move(light));
    }

    TrialResult result;
    result.frameMs = tools::median(frameMs);
    result.frameP99Ms = tools::percentile(allFrames, 0.99);
    result.frameMaxMs = tools::percentile(allFrames, 1.0);
    for (auto& [slot, views] : bySlot) {
        LightResult pooled = views.front();
        std::vector<double> ms;
        std::vector<truth::ShadowErrors> errors, areaErrors, nearErrors, softErrors;
        pooled.framesRendered = 0;
        pooled.nonFinitePixels = 0;
        for (const LightResult& view : views) {
            ms.push_back(view.shadowMs);
            errors.push_back(view.errors);
            areaErrors.push_back(view.areaErrors);
            nearErrors.push_back(view.nearErrors);
            softErrors.push_back(view.softErrors);
            pooled.framesRendered += view.framesRendered;
            pooled.nonFinitePixels += view.nonFinitePixels;
        }
        pooled.shadowMs = tools::median(ms);
        pooled.errors = pooledErrors(errors);
        pooled.areaErrors = pooledErrors(areaErrors);
        pooled.nearErrors = pooledErrors(nearErrors);
        pooled.softErrors = pooledErrors(softErrors);
        result.lights.push_back(std::move(pooled));
    }
    return result;
}

} // namespace evaluation
