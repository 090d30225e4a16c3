#include "OverlayText.h"

#include "shadowmap/ShadowViewSettings.h"

#include <cstdio>

namespace engine_view {

namespace {

const glm::u8vec4 kPlain{235, 235, 235, 255}, kSelected{255, 220, 90, 255}, kNote{140, 220, 255, 255},
    kError{255, 110, 100, 255}, kHelp{170, 170, 170, 255};

std::string format(const char* pattern, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

} // namespace

std::string OverlayText::lightSize(double size, engine::Light::Type type) {
    if (!(size > 0.0)) return "point";
    return format("size %g%s", size, type == engine::Light::Type::Directional ? " rad" : "");
}

std::string OverlayText::shadeSource(const engine::ShadeCacheReport& shadeCache, int slot) {
    const std::pair<const std::vector<int>*, const char*> sources[] = {
        {&shadeCache.fetched, "shade reused"}, {&shadeCache.computed, "shade computed"},
        {&shadeCache.moving, "shade moving"},  {&shadeCache.uncached, "shade live"},
        {&shadeCache.constant, "shade constant"}};
    for (const auto& [slots, text] : sources)
        if (std::find(slots->begin(), slots->end(), slot) != slots->end()) return text;
    return {};
}

void OverlayText::recordFrame(const engine::FrameResult& frame, const ViewerState& state) {
    for (const engine::ShadowView& view : frame.shadowViews) {
        bool ran = false;
        const double ms = frame.shadowPassMs(view, ran);
        if (ran) lastMs_[view.slot] = ms;
    }
}

std::vector<OverlayLine> OverlayText::lines(const ViewerState& state, const engine::FrameResult& frame,
                                            const std::vector<std::string>& notes, const std::string& camera,
                                            const std::string& animation, const std::string& status,
                                            bool statusIsError) const {
    std::vector<OverlayLine> out;
    const int selected = state.selected();
    out.push_back({format("frame %.1f ms   view: %s%s   camera: %s", frame.frameMs, viewName(state.view()),
                          selected >= 0 ? (" (" + state.lights()[selected].name + ")").c_str() : "", camera.c_str()),
                   kPlain});
    for (std::size_t i = 0; i < state.lights().size(); ++i) {
        const ViewedLight& light = state.lights()[i];
        const engine::ShadowView* view = state.frameView(static_cast<int>(i));
        const nlohmann::json settings = state.effective(static_cast<int>(i));
        std::string line = (static_cast<int>(i) == selected ? "> " : "   ") + light.name;
        if (!view) {
            line += "\t(no shadow plugin)";
        } else {
            const shadowmap::ShadowSettings used = shadowmap::usedSettings(*view);
            const glm::vec2 offset = used.effectivePolygonOffset();
            if (used.variant == shadowmap::Variant::Volume) {
                // No map: its resolution, format, filter and offsets mean nothing here. The
                // columns stay, so the other lights' line up.
                line += format("\t%s\tper pixel\t\t%s\thard\t\tdim %.2f", shadowmap::toString(used.variant),
                               lightSize(used.lightSize(light.type), light.type).c_str(),
                               settings.at("dimming").get<double>());
            } else {
                line += format("\t%s\t%d%s\t%s\t%s\t%s\toffset %g/%g\tdim %.2f", shadowmap::toString(used.variant),
                               used.resolution, view->cube ? " cube" : "", shadowmap::toString(used.depthFormat),
                               lightSize(used.lightSize(light.type), light.type).c_str(),
                               shadowmap::toString(used.filter), shadowmap::jsonNumber(offset.x),
                               shadowmap::jsonNumber(offset.y), settings.at("dimming").get<double>());
            }
            bool ran = false;
            const double ms = frame.shadowPassMs(*view, ran);
            // A volume light has no map but a visibility per pixel, timed and cached as a map is.
            if (!view->hasMap && !view->hasScreenVisibility) {
                line += "\tno map" + (view->skipReason.empty() ? std::string() : " (" + view->skipReason + ")");
            } else if (ran) {
                line += format("\t%.2f ms\trendered", ms);
            } else {
                const auto last = lastMs_.find(view->slot);
                line += last != lastMs_.end() ? format("\t%.2f ms\tcached", last->second) : std::string("\t\tcached");
            }
            line += '\t';
            line += shadeSource(frame.shadeCache, light.slot);
        }
        out.push_back({line, static_cast<int>(i) == selected ? kSelected : kPlain});
    }
    if (!animation.empty()) out.push_back({animation, kNote});
    for (const std::string& note : notes) out.push_back({note, kNote});
    if (!status.empty()) out.push_back({status, statusIsError ? kError : kNote});
    // Three short lines rather than two long ones: each fits a 1280-pixel window.
    out.push_back({"Tab light  V variant  R map size  F format  P filter  C cascades  T stable", kHelp});
    out.push_back({"- = light size  [ ] offset units  , . dimming  D view  1-9 glTF camera  0 framing", kHelp});
    out.push_back({"M texel density  drag: orbit (left), pan (right)  wheel zoom  O text  S save  Esc quit", kHelp});
    return out;
}

} // namespace engine_view
