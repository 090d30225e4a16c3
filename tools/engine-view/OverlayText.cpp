#include "OverlayText.h"

#include <cstdio>

namespace {

const glm::u8vec4 kPlain{235, 235, 235, 255}, kSelected{255, 220, 90, 255}, kNote{140, 220, 255, 255},
    kError{255, 110, 100, 255}, kHelp{170, 170, 170, 255};

std::string format(const char* pattern, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

} // namespace

bool OverlayText::lightPassMs(const engine::FrameResult& frame, const std::string& name, double& ms) {
    ms = 0.0;
    bool ran = false;
    for (const engine::PassReport& pass : frame.passes)
        if (!pass.culled && (pass.name == "shadow_" + name || pass.name == "shadow_" + name + "_first_layer")) {
            ms += pass.wallMs;
            ran = true;
        }
    return ran;
}

std::string OverlayText::shadeSource(const nlohmann::json& shadeCache, int slot) {
    static const std::pair<const char*, const char*> kSources[] = {
        {"fetched", "shade reused"}, {"computed", "shade computed"}, {"moving", "shade moving"},
        {"uncached", "shade live"}, {"constant", "shade constant"}};
    for (const auto& [key, text] : kSources) {
        const auto list = shadeCache.find(key);
        if (list == shadeCache.end() || !list->is_array()) continue;
        for (const nlohmann::json& entry : *list)
            if (entry.is_number_integer() && entry.get<int>() == slot) return text;
    }
    return {};
}

void OverlayText::recordFrame(const engine::FrameResult& frame, const ViewerState& state) {
    for (const ViewedLight& light : state.lights()) {
        double ms = 0.0;
        if (lightPassMs(frame, light.name, ms)) lastMs_[light.name] = ms;
    }
}

std::vector<OverlayLine> OverlayText::lines(const ViewerState& state, const engine::FrameResult& frame,
                                            const std::vector<std::string>& notes, const std::string& camera,
                                            const std::string& status, bool statusIsError) const {
    std::vector<OverlayLine> out;
    const int selected = state.selected();
    out.push_back({format("frame %.1f ms   view: %s%s   camera: %s", frame.frameMs, viewName(state.view()),
                          selected >= 0 ? (" (" + state.lights()[selected].name + ")").c_str() : "", camera.c_str()),
                   kPlain});
    for (std::size_t i = 0; i < state.lights().size(); ++i) {
        const ViewedLight& light = state.lights()[i];
        const nlohmann::json* stats = state.frameStats(static_cast<int>(i));
        const nlohmann::json settings = state.effective(static_cast<int>(i));
        std::string line = (static_cast<int>(i) == selected ? "> " : "   ") + light.name;
        if (!stats) {
            line += "\t(no shadow plugin)";
        } else {
            const std::string variant = stats->value("variant", "?");
            const std::string map = stats->value("map", "none");
            const nlohmann::json offset = stats->value("polygon_offset", nlohmann::json::array({0, 0}));
            line += format("\t%s\t%d%s\t%s\t%s\toffset %g/%g\tdim %.2f", variant.c_str(), stats->value("resolution", 0),
                           map == "cube" ? " cube" : "", stats->value("depth_format", "?").c_str(),
                           stats->value("filter", "?").c_str(), offset.at(0).get<double>(), offset.at(1).get<double>(),
                           settings.value("dimming", 0.4));
            double ms = 0.0;
            if (map == "none") {
                line += "\tno map" + (stats->contains("skip_reason") ? " (" + (*stats)["skip_reason"].get<std::string>() + ")"
                                                                       : std::string());
            } else if (lightPassMs(frame, light.name, ms)) {
                line += format("\t%.2f ms\trendered", ms);
            } else {
                const auto last = lastMs_.find(light.name);
                line += last != lastMs_.end() ? format("\t%.2f ms\tcached", last->second) : std::string("\t\tcached");
            }
            line += '\t';
            line += shadeSource(frame.shadeCache, light.slot);
        }
        out.push_back({line, static_cast<int>(i) == selected ? kSelected : kPlain});
    }
    for (const std::string& note : notes) out.push_back({note, kNote});
    if (!status.empty()) out.push_back({status, statusIsError ? kError : kNote});
    out.push_back({"Tab light  V variant  R size  F format  P filter  [ ] offset units  , . dimming", kHelp});
    out.push_back({"D view  1-9 glTF camera  0 framing  drag: orbit (left), pan (right)  wheel zoom  O text  S save  Esc quit",
                   kHelp});
    return out;
}
