#include "SceneMeasurer.h"

#include "engine/render/Frame.h"
#include "engine/util/Error.h"

#include "shadowmap/ShadowSettings.h"
#include "shadowmap/ShadowViewSettings.h"

#include <algorithm>
#include <map>

namespace shadowmap_tune {

namespace {

nlohmann::json shadowOf(const engine::Light& light) {
    const nlohmann::json& extras = light.extras;
    if (extras.is_object() && extras.contains("shadow") && extras["shadow"].is_object()) return extras["shadow"];
    return nlohmann::json::object();
}

} // namespace

SceneMeasurer::SceneMeasurer(engine::Scene& scene, const std::string& sceneFile, evaluation::SettingTrial& trial,
                             std::vector<SettingDimension> space, nlohmann::json configSettings)
    : scene_(scene), sceneFile_(sceneFile), trial_(trial), space_(std::move(space)), owned_(ownedKeys(space_)) {
    configured_ = nlohmann::json::object();
    for (const shadowmap::SettingKey& key : shadowmap::settingKeys())
        if (configSettings.is_object() && configSettings.contains(key.name)) configured_[key.name] = configSettings[key.name];
    for (const engine::Light& light : scene_.lights) loaded_.push_back(shadowOf(light));
    for (const engine::MeshInstance& instance : scene_.meshInstances) {
        const engine::Mesh& mesh = scene_.meshes.at(instance.mesh);
        const bool casts = instance.castShadows && std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                                               [](const engine::Primitive& p) { return p.castShadows; });
        if (!casts) continue;
        if (mesh.closed) {
            openCaster_.clear();
            break;
        }
        if (openCaster_.empty()) openCaster_ = mesh.name.empty() ? "mesh " + std::to_string(instance.mesh) : mesh.name;
    }
}

void SceneMeasurer::measureCurrent() {
    if (scene_.lightInstances.empty())
        engine::throwInputError(sceneFile_, "", "the scene has no lights: nothing to tune");
    const evaluation::TrialResult result = trial_.measure();
    // The tuned lights, in the order of their first instance; their current settings as the
    // plugin resolved them (its public ShadowView::settings), in the search space's terms.
    for (const evaluation::LightResult& view : result.lights) {
        const int light = scene_.lightInstances.at(view.slot).light;
        if (std::find(lights_.begin(), lights_.end(), light) != lights_.end()) continue;
        lights_.push_back(light);
        names_.push_back(scene_.lights[light].name.empty() ? view.light : scene_.lights[light].name);
    }
    if (lights_.empty())
        engine::throwInputError(sceneFile_, "", "no light casts a shadow (every light's variant is none): nothing to tune");
    const std::vector<std::optional<Measured>> measured = collect(result);
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        Measured current = *measured[i];
        for (const evaluation::LightResult& view : result.lights)
            if (scene_.lightInstances.at(view.slot).light == lights_[i]) {
                // The plugin reports the offset in effect; it is the light's own only when the
                // file or the config sets it (else it is the variant's default: left out,
                // as the search's candidates leave it).
                const bool explicitOffset = loaded_[lights_[i]].contains("polygon_offset") ||
                                            configured_.contains("polygon_offset");
                const shadowmap::ShadowSettings settings = shadowmap::usedSettings(view.view);
                const nlohmann::json used = shadowmap::printSettings(settings);
                current.setting = candidateOf(space_, used);
                if (explicitOffset && used.contains("polygon_offset")) current.setting["polygon_offset"] = used["polygon_offset"];
                normalOffsets_.push_back(settings.normalOffset);
                rankingTruths_.push_back(evaluation::rankingTruth(view));
                break;
            }
        current_.push_back(current);
    }
}

std::vector<std::optional<Measured>> SceneMeasurer::collect(const evaluation::TrialResult& result) const {
    std::map<int, std::vector<const evaluation::LightResult*>> byLight;
    for (const evaluation::LightResult& view : result.lights)
        byLight[scene_.lightInstances.at(view.slot).light].push_back(&view);
    std::vector<std::optional<Measured>> out(lights_.size());
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const auto found = byLight.find(lights_[i]);
        if (found == byLight.end()) continue;
        Measured m;
        std::vector<truth::ShadowErrors> errors, rankedErrors;
        for (const evaluation::LightResult* instance : found->second) {
            m.ms += instance->shadowMs;
            errors.push_back(instance->errors);
            rankedErrors.push_back(evaluation::rankedErrors(*instance));
        }
        const truth::ShadowErrors pooled = evaluation::pooledErrors(errors);
        const truth::ShadowErrors ranked = evaluation::pooledErrors(rankedErrors);
        m.acne = 100.0 * ranked.acne;
        m.leak = 100.0 * ranked.leak;
        m.error = 100.0 * ranked.error;
        m.penumbraError = 100.0 * ranked.penumbraError;
        m.evaluatedPenumbra = ranked.evaluatedPenumbra;
        m.errorNoEdge = 100.0 * pooled.errorNoEdge;
        m.evaluated = pooled.evaluated;
        out[i] = m;
    }
    return out;
}

std::vector<std::optional<Measured>> SceneMeasurer::measure(const std::vector<Candidate>& perLight) {
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        // From the file's keys each time, so nothing of an earlier candidate lingers.
        scene_.lights[lights_[i]].extras["shadow"] = loaded_[lights_[i]];
        evaluation::setLightShadow(scene_, lights_[i], perLight.at(i), owned_);
    }
    return collect(trial_.measure());
}

bool SceneMeasurer::valid(int tuned, const Candidate& candidate) const {
    if (!openCaster_.empty() && candidate.value("variant", "") == shadowmap::toString(shadowmap::Variant::Backface))
        return false;
    nlohmann::json shadow = loaded_[lights_.at(tuned)];
    for (const std::string& key : owned_) shadow.erase(key);
    for (const auto& [key, value] : candidate.items()) shadow[key] = value;
    try {
        shadowmap::ShadowSettings settings = shadowmap::parseSettings(configured_, "engine config", "defaults");
        shadowmap::applySettings(settings, shadow, sceneFile_, "light");
        shadowmap::checkLimits(settings, static_cast<int>(*shadowmap::settingKey("resolution").maximum), sceneFile_,
                               "light");
        shadowmap::checkFilterForType(settings, scene_.lights.at(lights_.at(tuned)).type, sceneFile_, "light");
        return true;
    } catch (const engine::InputError&) {
        return false;
    }
}

} // namespace shadowmap_tune
