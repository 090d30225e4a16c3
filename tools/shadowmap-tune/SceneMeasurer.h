#pragma once
// The search's measuring function on a real scene: writes one candidate into each tuned
// light's extras.shadow, runs one SettingTrial (every view, timed frames, truth) and hands
// back each light's time and pooled error against the truth it is ranked by
// (evaluation::rankingTruth). Lights are glTF light objects (extras.shadow lives there); a
// light used by several instances sums their times and pools their errors.
#include "Search.h"

#include "SettingTrial.h"

#include "engine/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowmap_tune {

class SceneMeasurer {
public:
    // `configSettings`: the shadow plugin's settings in the engine config (the defaults).
    SceneMeasurer(engine::Scene& scene, const std::string& sceneFile, evaluation::SettingTrial& trial,
                  std::vector<SettingDimension> space, nlohmann::json configSettings);

    // The first render: every light as the file sets it. Finds the lights to tune (those
    // with a shadow among the lit pass's lights) and their current settings; an InputError
    // naming the scene when there is none.
    void measureCurrent();
    const std::vector<int>& lights() const { return lights_; }  // glTF light indices, tuned order
    const std::vector<std::string>& names() const { return names_; }
    const std::vector<Measured>& current() const { return current_; }
    // Per tuned light, as the plugin resolved it at the first render: the normal offset
    // candidates without one are measured with, and the truth its errors are against (a
    // light's size is no key the tuner sets, so neither changes while it searches).
    const std::vector<double>& normalOffsets() const { return normalOffsets_; }
    const std::vector<evaluation::RankingTruth>& rankingTruths() const { return rankingTruths_; }

    std::vector<std::optional<Measured>> measure(const std::vector<Candidate>& perLight);
    // Whether the plugin's settings API accepts the candidate over the light's other keys
    // (e.g. reversed_z needs d32f), and, for backface, whether every caster is closed.
    bool valid(int tuned, const Candidate& candidate) const;
    // A shadow-casting mesh that is not closed, when no caster is closed (else empty). The
    // plugin draws open casters two-sided with the standard offset under backface, so with
    // no closed caster backface is standard by another name and would compete with it on
    // timing noise alone: left out. With some closed casters it differs, and is searched.
    const std::string& onlyOpenCasters() const { return openCaster_; }

private:
    std::vector<std::optional<Measured>> collect(const evaluation::TrialResult& result) const;

    engine::Scene& scene_;
    std::string sceneFile_;
    evaluation::SettingTrial& trial_;
    std::vector<SettingDimension> space_;
    std::vector<std::string> owned_;  // ownedKeys(space_)
    nlohmann::json configured_;  // the config's per-light keys only
    std::vector<nlohmann::json> loaded_;  // per scene light: extras.shadow as loaded
    std::vector<int> lights_;
    std::vector<std::string> names_;
    std::vector<Measured> current_;
    std::vector<double> normalOffsets_;
    std::vector<evaluation::RankingTruth> rankingTruths_;
    std::string openCaster_;
};

} // namespace shadowmap_tune
