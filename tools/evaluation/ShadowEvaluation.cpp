#include "ShadowEvaluation.h"

#include "Median.h"

#include "truth/TexelDensityImage.h"

#include "engine/scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace evaluation {

ShadowEvaluator::ShadowEvaluator(engine::Renderer& renderer, const engine::Scene& scene)
    : renderer_(renderer), scene_(scene), visibility_(scene) {}

TexelOnScreen summarizeTexelOnScreen(const std::vector<double>& m) {
    std::vector<double> values;
    for (double value : m)
        if (std::isfinite(value)) values.push_back(value);
    if (values.empty()) return {};
    double sum = 0.0;
    for (double value : values) sum += value;
    const double mean = sum / static_cast<double>(values.size());
    return {mean, tools::percentile(values, kTexelPercentile), values.size()};
}

bool ShadowEvaluator::scored(const engine::ShadowView& view) const {
    return view.castsShadows && scene_.lights[scene_.lightInstances[view.slot].light].emitsLight();
}

ViewResult ShadowEvaluator::evaluate(const engine::FrameCamera& camera, int frames) {
    ViewResult result;
    engine::FrameRequest request;
    request.camera = camera;
    request.timing = true;

    std::vector<double> frameMs;
    std::map<int, std::vector<double>> lightMs;  // by slot
    for (int frame = 0; frame < frames; ++frame) {
        const engine::FrameResult timed = renderer_.renderFrame(request);
        frameMs.push_back(timed.frameMs);
        for (const engine::ShadowView& view : timed.shadowViews) {
            bool ran = false;
            const double ms = timed.shadowPassMs(view, ran);
            if (ran) lightMs[view.slot].push_back(ms);
        }
    }
    result.frameMs = tools::median(frameMs);
    result.frameTimes = frameMs;
    if (frames > 0) result.image = renderer_.readColor();

    // One more frame, untimed, with every shadowed light's mask.
    request.timing = false;
    const std::vector<engine::ShadowView> views = renderer_.renderFrame(request).shadowViews;
    for (const engine::ShadowView& view : views)
        if (scored(view)) request.shadowMaskSlots.push_back(view.slot);
    if (request.shadowMaskSlots.empty()) return result;
    renderer_.renderFrame(request);

    const truth::SurfaceBuffer surfaces = capture_.capture(scene_, renderer_.gpu(), camera);
    for (const engine::ShadowView& view : views) {
        if (!scored(view)) continue;
        LightResult out;
        out.light = view.name;
        out.slot = view.slot;
        out.view = view;
        out.shadowMs = tools::median(lightMs[view.slot]);
        out.framesRendered = static_cast<int>(lightMs[view.slot].size());
        const std::vector<float> shade = truth::shadeFromMask8(renderer_.readShadowMask(out.slot));
        for (float value : shade) out.nonFinitePixels += !std::isfinite(value);
        const auto truthImage = visibility_.visibility(scene_, out.slot, surfaces);
        const auto evaluationSet = truth::evaluationSet(scene_, out.slot, surfaces);
        out.errors = truth::shadowErrors(camera.width, camera.height, truthImage, shade, evaluationSet,
                                         surfaces.covered);
        if (nearDistance_ > 0.0) {
            std::vector<std::uint8_t> near = evaluationSet;
            for (std::size_t i = 0; i < near.size(); ++i)
                near[i] = near[i] && glm::length(surfaces.worldPosition[i] - surfaces.cameraPosition) < nearDistance_;
            out.nearErrors = truth::shadowErrors(camera.width, camera.height, truthImage, shade, near, surfaces.covered);
        }
        if (areaTruth_)
            out.areaErrors = truth::areaShadowErrors(camera.width, camera.height,
                                                     visibility_.litFraction(scene_, out.slot, surfaces),
                                                     truthImage, shade, evaluationSet, surfaces.covered);
        // The same image engine-render --texel-density paints: its figures describe that picture.
        out.texelOnScreen = summarizeTexelOnScreen(truth::texelOnScreenImage(view, surfaces, evaluationSet));
        std::vector<float> softTruth;
        if (const truth::LightExtent extent = lightExtent(view); !extent.isPoint()) {
            softTruth = visibility_.visibleFraction(scene_, out.slot, surfaces, extent);
            out.softErrors = truth::softShadowErrors(camera.width, camera.height, softTruth, shade, evaluationSet,
                                                     surfaces.covered);
        }
        if (keepTruth_) {
            out.truth = softTruth.empty() ? std::vector<float>(truthImage.begin(), truthImage.end())
                                          : std::move(softTruth);
            out.evaluated = evaluationSet;
        }
        result.lights.push_back(std::move(out));
    }
    return result;
}

std::vector<LightShimmer> ShadowEvaluator::shimmer(const std::vector<engine::FrameCamera>& path) {
    std::vector<LightShimmer> lights;
    if (path.empty()) return lights;
    engine::FrameRequest request;
    request.camera = path.front();
    for (const engine::ShadowView& view : renderer_.renderFrame(request).shadowViews)
        if (scored(view)) {
            request.shadowMaskSlots.push_back(view.slot);
            lights.push_back({view.name, view.slot, {}});
        }
    if (lights.empty()) return lights;

    // The previous frame's capture and, per light, its mask, truth and evaluation set.
    struct LightFrame {
        std::vector<std::uint8_t> mask, truth, evaluated;
    };
    truth::SurfaceBuffer previous;
    std::vector<LightFrame> previousLights;
    for (std::size_t frame = 0; frame < path.size(); ++frame) {
        request.camera = path[frame];
        renderer_.renderFrame(request);
        truth::SurfaceBuffer surfaces = capture_.capture(scene_, renderer_.gpu(), request.camera);
        std::vector<LightFrame> current;
        for (LightShimmer& light : lights) {
            LightFrame here{renderer_.readShadowMask(light.slot), visibility_.visibility(scene_, light.slot, surfaces),
                            truth::evaluationSet(scene_, light.slot, surfaces)};
            if (frame > 0) {
                const LightFrame& before = previousLights[current.size()];
                light.count += truth::shimmerBetween({&previous, before.mask, before.truth, before.evaluated},
                                                     {&surfaces, here.mask, here.truth, here.evaluated});
            }
            current.push_back(std::move(here));
        }
        previous = std::move(surfaces);
        previousLights = std::move(current);
    }
    return lights;
}

} // namespace evaluation
