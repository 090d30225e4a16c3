// The smallest plugin: one pass in every frame's graph, and a setting. It counts the frames
// it ran in and reports the count in the frame's plugin stats.
//
// Load it by naming it in an engine config:
//   {"plugin_dirs": ["path/to/dir/of/the/.so"],
//    "plugins": [{"library": "pass_counter_plugin", "settings": {"label": "hello"}}]}
#include "engine/graph/RenderGraph.h"
#include "engine/plugin/RenderPlugin.h"
#include "engine/render/Frame.h"
#include "engine/util/Error.h"

#include <engine_plugin/PluginAbi.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>

namespace {

class PassCounterPlugin final : public engine::RenderPlugin {
public:
    explicit PassCounterPlugin(std::string label) : label_(std::move(label)) {}

    std::string name() const override { return "pass_counter"; }

    void addPasses(engine::Frame& frame) override {
        frame.graph().addPass(
            "count_" + label_,
            // A pass that writes nothing anybody reads would be culled: declare the side
            // effect. A real pass would create or write textures here instead.
            [](engine::PassBuilder& builder) { builder.sideEffect(); },
            [this](engine::PassContext&) { ++framesRun_; });
    }

    nlohmann::json frameStats() const override { return {{"label", label_}, {"frames_run", framesRun_}}; }

private:
    std::string label_;
    int framesRun_ = 0;
};

// Settings arrive as JSON text. Refusing an unknown key with an InputError is what every
// plugin should do: a typo must not silently change nothing.
void registerPassCounter(engine::PluginRegistry* registry, const char* settingsJson) {
    const nlohmann::json settings = nlohmann::json::parse(settingsJson);
    std::string label = "frames";
    for (const auto& [key, value] : settings.items()) {
        if (key != "label" || !value.is_string())
            throw engine::InputError("setting \"" + key + "\": the pass counter takes only \"label\" (a string)");
        label = value.get<std::string>();
    }
    registry->addRenderPlugin(std::make_unique<PassCounterPlugin>(label));
}

} // namespace

ENGINE_DECLARE_PLUGIN("pass_counter", &registerPassCounter)
