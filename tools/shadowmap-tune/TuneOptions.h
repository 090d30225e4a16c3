#pragma once
// shadowmap-tune's command line. Parsing checks every value and throws
// std::invalid_argument with one line naming the flag and the value.
#include "OptionValues.h"
#include "SceneLighting.h"
#include "SearchSpace.h"

#include "engine/scene/Scene.h"

#include <optional>
#include <string>

namespace shadowmap_tune {

// --views: every glTF camera, or N views around the scene.
struct ViewSpec {
    enum class Kind { Cameras, Orbit };
    Kind kind = Kind::Cameras;
    int count = 0;  // Orbit: N
    bool given = false;  // false: cameras when the scene has any, else orbit:4
};

struct TuneOptions {
    std::string config;  // default: tools::defaultConfigPath()
    std::string scene;
    std::string out;
    std::string report;  // optional JSON report
    bool budget = false;  // --budget-ms given (else --max-error)
    double limit = 0.0;   // ms or percent
    ViewSpec views;
    int width = 0, height = 0, frames = 0;
    SearchLimits limits;
    // --key-light (and --key-light-angles): a scene without lights gets this key light (placed
    // as engine-render and the bench place it), which is tuned and written into --out with its
    // setting. --ground: a ground under the model receives the shadows while measuring, as
    // engine-render --ground shows them; it is not written into --out.
    tools::SceneLighting lighting;
    tools::Shard shard;               // --shard K/N: --out is then a partial result (JSON)
    std::vector<std::string> merge;   // --merge PART.json...: write --out from these, render nothing
    bool help = false;
};

ViewSpec parseViewSpec(const std::string& flag, const std::string& text);

const char* tuneUsage();

TuneOptions parseTuneOptions(int argc, char** argv);

} // namespace shadowmap_tune
