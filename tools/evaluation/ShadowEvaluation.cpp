#include "ShadowEvaluation.h"

#include "engine/scene/Scene.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace evaluation {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

ShadowEvaluator::ShadowEvaluator(engine::Renderer& renderer, const engine::Scene& scene)
    : renderer_(renderer), scene_(scene), visibility_(scene) {}

namespace {

// The shadow plugin names a light's passes "shadow_<light>" (and, for woo,
// "shadow_<light>_first_layer"); a frame's share of a light is the sum of those.
double lightPassMs(const engine::FrameResult& frame, const std::string& light, bool& ran) {
    double total = 0.0;
    ran = false;
    for (const engine::PassReport& pass : frame.passes)
        if (!pass.culled && (pass.name == "shadow_" + light || pass.name == "shadow_" + light + "_first_layer")) {
            total += pass.wallMs;
            ran = true;
        }
    return total;
}

} // namespace

ViewResult ShadowEvaluator::evaluate(const engine::FrameCamera& camera, int frames) {
    ViewResult result;
    engine::FrameRequest request;
    request.camera = camera;
    request.timing = true;

    std::vector<double> frameMs;
    std::map<std::string, std::vector<double>> lightMs;
    engine::FrameResult last;
    for (int frame = 0; frame < frames; ++frame) {
        last = renderer_.renderFrame(request);
        frameMs.push_back(last.frameMs);
        for (const nlohmann::json& light : last.pluginStats["shadowmap"]["lights"]) {
            bool ran = false;
            const double ms = lightPassMs(last, light["light"], ran);
            if (ran) lightMs[light["light"]].push_back(ms);
        }
    }
    result.frameMs = median(frameMs);
    if (frames > 0) result.image = renderer_.readColor();

    // One more frame, untimed, with every shadowed light's mask.
    request.timing = false;
    const nlohmann::json lightStats = renderer_.renderFrame(request).pluginStats["shadowmap"]["lights"];
    for (const nlohmann::json& light : lightStats)
        if (light["variant"] != "none") request.shadowMaskSlots.push_back(light["slot"]);
    if (request.shadowMaskSlots.empty()) return result;
    renderer_.renderFrame(request);

    const truth::SurfaceBuffer surfaces = capture_.capture(scene_, renderer_.gpu(), camera);
    for (const nlohmann::json& light : lightStats) {
        if (light["variant"] == "none") continue;
        LightResult out;
        out.light = light["light"];
        out.slot = light["slot"];
        out.stats = light;
        out.shadowMs = median(lightMs[out.light]);
        out.framesRendered = static_cast<int>(lightMs[out.light].size());
        const std::vector<float> shade = truth::shadeFromMask8(renderer_.readShadowMask(out.slot));
        for (float value : shade) out.nonFinitePixels += !std::isfinite(value);
        const auto truthImage = visibility_.visibility(scene_, out.slot, surfaces);
        const auto evaluationSet = truth::evaluationSet(scene_, out.slot, surfaces);
        out.errors = truth::shadowErrors(camera.width, camera.height, truthImage, shade, evaluationSet,
                                         surfaces.covered);
        result.lights.push_back(std::move(out));
    }
    return result;
}

} // namespace evaluation
