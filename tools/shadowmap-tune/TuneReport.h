#pragma once
// What shadowmap-tune tells: per light, old -> new setting with time and error before and
// after (named by the truth the light is ranked by: "soft error" or "area error"), the fitted
// polygon and normal offsets beside the defaults and the lattice they were fitted on; the
// renders the search took against the full grid. As lines for people and as JSON (--report)
// for scripts and tests.
#include "Search.h"

#include "SettingTrial.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shadowmap_tune {

struct TuneSummary {
    std::vector<std::string> names;       // per tuned light
    std::vector<evaluation::RankingTruth> truths;  // per tuned light: what its errors are against
    std::vector<LightChoice> choices;     // per tuned light
    std::vector<std::vector<Measured>> measured;  // per tuned light: every setting measured
    int renders = 0;                      // trials run, the first (current settings) included
    long gridPerLight = 0;                // settings in the full grid, per light
    int views = 0;
    int width = 0, height = 0;            // the image size every view was measured at
    Goal goal;
};

std::string reportText(const TuneSummary& summary, const std::vector<SettingDimension>& space);
nlohmann::json reportJson(const TuneSummary& summary, const std::vector<SettingDimension>& space);

} // namespace shadowmap_tune
