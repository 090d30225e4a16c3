// shadowmap-tune: chooses each light's shadow setting by measuring time and error against
// ray-traced truth, and writes it into the scene's extras.shadow.
#include "ToolMain.h"
#include "OffsetFit.h"
#include "SceneMeasurer.h"
#include "Search.h"
#include "SearchSpace.h"
#include "TuneOptions.h"
#include "TuneReport.h"
#include "TuneShards.h"
#include "TuneViews.h"

#include "AssetExtras.h"
#include "SaveSettings.h"
#include "SceneLighting.h"
#include "SavedShadow.h"
#include "SettingTrial.h"
#include "ShadowPluginConfig.h"

#include "engine/config/EngineConfig.h"
#include "engine/context/GlContext.h"
#include "engine/gltf/GltfLoader.h"
#include "engine/plugin/PluginHost.h"
#include "engine/render/Renderer.h"
#include "engine/util/Error.h"
#include "engine/util/OutputFile.h"
#include "engine/util/ProcessSetup.h"

#include <cstdio>
#include <iostream>
#include <map>

namespace shadowmap_tune {
namespace {

nlohmann::json loadedShadow(const engine::Light& light) {
    const nlohmann::json& extras = light.extras;
    if (extras.is_object() && extras.contains("shadow") && extras["shadow"].is_object()) return extras["shadow"];
    return nlohmann::json::object();
}

// A light no measured setting satisfies: one line naming the light, the goal and the
// nearest miss.
void refuseInfeasible(const TuneOptions& options, const std::string& name, const LockstepMeasurer& measurer, int light,
                      const Goal& goal, const std::vector<SettingDimension>& space) {
    const Measured* nearest = nullptr;
    for (const Measured& m : measurer.measured(light))
        if (!nearest || goal.better(m, *nearest)) nearest = &m;
    char text[256];
    if (goal.kind == Goal::Kind::Budget)
        std::snprintf(text, sizeof text, "no setting fits --budget-ms %g (the fastest measured, %s, takes %.2f ms)",
                      goal.limit, describe(nearest->setting, space).c_str(), nearest->ms);
    else
        std::snprintf(text, sizeof text, "no setting reaches --max-error %g (the most accurate measured, %s, errs %.3f%%)",
                      goal.limit, describe(nearest->setting, space).c_str(), nearest->error);
    engine::throwInputError(options.scene, "light \"" + name + "\"", std::string(text) + "; no file written");
}

// --merge: every partial result is read and checked before the scene is written.
int merge(const TuneOptions& options) {
    const MergedResult merged = mergePartialResults(options.merge, options.scene);
    tools::saveSceneSettings(options.scene, options.out, merged.shadows, {}, {{tools::kTunedForKey, merged.tunedFor}});
    std::fprintf(stderr, "shadowmap-tune: merged %zu partial results; wrote %s (%zu light(s) changed)\n",
                 options.merge.size(), options.out.c_str(), merged.shadows.size());
    return 0;
}

int run(const TuneOptions& options, std::unique_ptr<engine::GlContext>& context, engine::PluginHost& host) {
    if (!options.merge.empty()) return merge(options);
    engine::tuneAllocatorForRendering();
    engine::EngineConfig config = engine::loadEngineConfig(options.config);
    const nlohmann::json configSettings = tools::shadowPluginSettings(config);
    tools::disableShadowMapCaching(config, options.config);

    // Every check that needs no render comes first: bad input fails before minutes of work.
    std::vector<std::string> warnings;
    engine::Scene scene = engine::loadGltf(options.scene, &warnings);
    for (const std::string& warning : warnings) std::cerr << "warning: " << warning << "\n";
    // The key light only where the scene has none, as the bench adds it; the ground either way.
    tools::SceneLighting lighting = options.lighting;
    if (!scene.lightInstances.empty() && lighting.keyLight) {
        std::fprintf(stderr, "shadowmap-tune: %s has lights: --key-light ignored\n", options.scene.c_str());
        lighting.keyLight.reset();
    }
    const bool addsKeyLight = lighting.keyLight.has_value();
    if (addsKeyLight || lighting.ground)
        for (const std::string& note : tools::stageScene(scene, options.scene, lighting).notes)
            std::fprintf(stderr, "shadowmap-tune: %s\n", note.c_str());
    const int keyLightNode = addsKeyLight ? scene.lightInstances.at(0).node : -1;
    if (scene.lightInstances.empty())
        engine::throwInputError(options.scene, "", "the scene has no lights: nothing to tune (add one with --key-light)");
    const bool sharded = options.shard.count > 1;
    if (!sharded) tools::checkSaveTarget(options.scene, options.out);
    else engine::checkOutputPath(options.out);
    if (!options.report.empty()) engine::checkOutputPath(options.report);
    const std::vector<engine::FrameCamera> views =
        tuneViews(scene, options.views, options.width, options.height, options.scene);
    std::vector<nlohmann::json> loaded;
    for (const engine::Light& light : scene.lights) loaded.push_back(loadedShadow(light));

    const std::vector<SettingDimension> space = searchSpace(options.limits);
    const Goal goal{options.budget ? Goal::Kind::Budget : Goal::Kind::MaxError, options.limit,
                    static_cast<long>(options.width) * options.height};

    context = engine::createEglContext();
    context->makeCurrent();
    host.loadAll(config);
    engine::Renderer renderer(config.renderer, host.renderPlugins());
    evaluation::SettingTrial trial(renderer, scene, views, options.frames);
    // A point light is ranked by its area error (evaluation::rankingTruth): against one ray
    // per pixel a filtered shade that matches the penumbra a pixel really sees scores worse
    // than a hard edge. A light with a size is ranked by its soft error, always measured.
    trial.setAreaTruth(true);
    SceneMeasurer sceneMeasurer(scene, options.scene, trial, space, configSettings);
    sceneMeasurer.measureCurrent();

    if (!sceneMeasurer.onlyOpenCasters().empty())
        std::fprintf(stderr, "shadowmap-tune: backface left out: no caster is closed (e.g. \"%s\")\n",
                     sceneMeasurer.onlyOpenCasters().c_str());
    const int lights = static_cast<int>(sceneMeasurer.lights().size());
    LockstepMeasurer measurer(
        lights, [&](const std::vector<Candidate>& perLight) { return sceneMeasurer.measure(perLight); },
        [&](int light, const Candidate& candidate) { return sceneMeasurer.valid(light, candidate); });
    for (int light = 0; light < lights; ++light)
        measurer.seed(light, sceneMeasurer.current()[light], sceneMeasurer.normalOffsets()[light]);
    std::vector<bool> searched(lights);
    for (int light = 0; light < lights; ++light) searched[light] = inShard(options.shard, light);
    const std::vector<LightChoice> choices = searchSettings(measurer, space, goal, searched);

    TuneSummary summary{sceneMeasurer.names(), sceneMeasurer.rankingTruths(), choices, {}, trial.renders(),
                        gridSize(space, kOffsetLatticeSize), static_cast<int>(views.size()), options.width,
                        options.height, goal};
    for (int light = 0; light < lights; ++light) summary.measured.push_back(measurer.measured(light));
    std::fputs(reportText(summary, space).c_str(), stdout);
    std::fflush(stdout);  // before stderr's lines
    for (int light = 0; light < lights; ++light)
        if (searched[light] && !goal.feasible(choices[light].chosen))
            refuseInfeasible(options, sceneMeasurer.names()[light], measurer, light, goal, space);

    // Only changed lights are edited: a light whose setting stays keeps its bytes. The key
    // light is not in the file: it is added with its setting, changed or not.
    const int keyLight = keyLightNode >= 0 ? scene.nodes[keyLightNode].light : -1;
    std::map<int, nlohmann::json> shadows;
    std::vector<tools::AddedLight> added;
    for (int light = 0; light < lights; ++light) {
        const int index = sceneMeasurer.lights()[light];
        if (!choices[light].changed && index != keyLight) continue;
        nlohmann::json shadow = loaded[index];
        for (const std::string& key : ownedKeys(space)) shadow.erase(key);
        for (const auto& [key, value] : choices[light].chosen.setting.items()) shadow[key] = value;
        const nlohmann::json saved = tools::savedShadow(configSettings, loaded[index], shadow);
        if (index == keyLight) added.push_back(tools::addedLightOf(scene, keyLightNode, saved));
        else shadows[index] = saved;
    }
    // What the choice holds for, recorded in the tuned file (AssetExtras.h).
    const nlohmann::json tunedFor = tools::tunedSizeRecord({options.width, options.height});
    if (sharded)
        engine::writeFileAtomically(options.out, partialResult(options.scene, options.shard, tunedFor, shadows));
    else tools::saveSceneSettings(options.scene, options.out, shadows, added, {{tools::kTunedForKey, tunedFor}});
    if (!options.report.empty())
        engine::writeFileAtomically(options.report, reportJson(summary, space).dump(2) + "\n");
    std::fprintf(stderr, "shadowmap-tune: wrote %s (%zu light(s) changed%s)\n", options.out.c_str(), shadows.size(),
                 added.empty() ? "" : ", the key light added with its setting");
    return 0;
}

} // namespace
} // namespace shadowmap_tune

int main(int argc, char** argv) {
    return tools::toolMain("shadowmap-tune", shadowmap_tune::tuneUsage(), argc, argv, shadowmap_tune::parseTuneOptions,
                           [](const auto& options, tools::ToolSession& session) {
                               return shadowmap_tune::run(options, session.context, session.host);
                           });
}
