#include "ViewerState.h"

#include "SavedShadow.h"

#include "engine/render/Frame.h"
#include "engine/util/Error.h"

#include "shadowmap/ShadowSettings.h"
#include "shadowmap/ShadowViewSettings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace engine_view {

namespace {

constexpr std::array<const char*, kDebugViewCount> kViewNames = {
    "shaded", "light", "depth", "projected", "comparison", "shadow", "penumbra", "truth", "cascades", "density"};

// The smallest sizes the keys give, one step up from 0: a 1 cm radius (world units are
// metres in glTF), and 2 mrad, about a fifth of the sun's 0.0093.
constexpr double kSmallestLightRadius = 0.01;
constexpr double kSmallestAngularDiameter = 0.002;
// The ladder's sizes keep this many significant digits, so the saved glTF reads 0.0225,
// not 0.022500000000000003.
constexpr int kLightSizeDigits = 4;

double roundToSignificant(double value, int digits) {
    if (!(value > 0.0)) return value;
    const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(value))));
    return std::round(value * scale) / scale;
}

// The value after `current` among a key's allowed values (the first when `current` is
// none of them), so the keys cycle through exactly what the plugin accepts.
std::string nextChoice(const char* key, const std::string& current) {
    const std::vector<std::string>& choices = shadowmap::settingKey(key).choices;
    const auto found = std::find(choices.begin(), choices.end(), current);
    return found == choices.end() || found + 1 == choices.end() ? choices.front() : *(found + 1);
}

} // namespace

const char* viewName(DebugView view) { return kViewNames[static_cast<int>(view)]; }

std::optional<DebugView> parseView(const std::string& name) {
    for (int i = 0; i < kDebugViewCount; ++i)
        if (name == kViewNames[i]) return static_cast<DebugView>(i);
    return std::nullopt;
}

void ViewerState::toggleTexelDensity() {
    if (view_ == DebugView::TexelDensity) {
        view_ = beforeTexelDensity_;
        return;
    }
    beforeTexelDensity_ = view_;
    view_ = DebugView::TexelDensity;
}

std::string viewNames() {
    std::string names;
    for (const char* name : kViewNames) names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

const char* lightSizeKey(engine::Light::Type type) {
    return type == engine::Light::Type::Directional ? "angular_diameter" : "light_radius";
}

double smallestLightSize(engine::Light::Type type) {
    return type == engine::Light::Type::Directional ? kSmallestAngularDiameter : kSmallestLightRadius;
}

double stepLightSize(double size, engine::Light::Type type, bool grow) {
    const double smallest = smallestLightSize(type);
    if (grow && size < smallest) return smallest;
    // Never below 0 (the plugin refuses a negative size): the smallest size, then 0.
    if (!grow && size <= smallest) return 0.0;
    // The keys walk the ladder smallest * kLightSizeStep^k, so a step down undoes a step up
    // exactly; a size set otherwise (script, file) steps to the next rung in the key's way.
    const auto rung = [&](int k) { return roundToSignificant(smallest * std::pow(kLightSizeStep, k), kLightSizeDigits); };
    const int estimate = static_cast<int>(std::floor(std::log(size / smallest) / std::log(kLightSizeStep)));
    int k = std::max(estimate - 1, 0);
    if (grow) {
        while (rung(k) <= size) ++k;
    } else {
        k = estimate + 1;
        while (k > 0 && rung(k) >= size) --k;
    }
    return rung(k);
}

ViewerState::ViewerState(engine::Scene& scene, nlohmann::json pluginDefaults)
    : scene_(scene), defaults_(std::move(pluginDefaults)) {
    if (!defaults_.is_object()) defaults_ = nlohmann::json::object();
    // The lights the renderer shades with its lit pass chosen as by default ("auto").
    const int rendered = engine::renderedLightCount(std::nullopt, scene.lightInstances.size());
    for (int slot = 0; slot < rendered; ++slot) {
        const engine::LightInstance& placed = scene.lightInstances[slot];
        ViewedLight light;
        light.name = scene.lights[placed.light].name;
        if (light.name.empty()) light.name = scene.nodes[placed.node].name;
        light.slot = slot;
        light.light = placed.light;
        light.type = scene.lights[placed.light].type;
        lights_.push_back(light);
    }
    for (const engine::Light& light : scene.lights) {
        applied_.push_back(light.extras);
        const bool hasShadow = light.extras.is_object() && light.extras.contains("shadow") && light.extras["shadow"].is_object();
        loaded_.push_back(hasShadow ? light.extras["shadow"] : nlohmann::json::object());
    }
    selected_ = lights_.empty() ? -1 : 0;
}

void ViewerState::selectNext() {
    if (!lights_.empty()) selected_ = (selected_ + 1) % static_cast<int>(lights_.size());
}

int ViewerState::find(const std::string& name) const {
    for (std::size_t i = 0; i < lights_.size(); ++i)
        if (lights_[i].name == name) return static_cast<int>(i);
    return -1;
}

bool ViewerState::select(const std::string& name) {
    const int index = find(name);
    if (index >= 0) selected_ = index;
    return index >= 0;
}

nlohmann::json& ViewerState::shadowOf(int index) {
    nlohmann::json& extras = scene_.lights[lights_[index].light].extras;
    if (!extras.is_object()) extras = nlohmann::json::object();
    nlohmann::json& shadow = extras["shadow"];
    if (!shadow.is_object()) shadow = nlohmann::json::object();
    return shadow;
}

const engine::ShadowView* ViewerState::frameView(int index) const {
    for (const engine::ShadowView& view : views_)
        if (view.slot == lights_[index].slot) return &view;
    return nullptr;
}

nlohmann::json ViewerState::effective(int index) const {
    nlohmann::json settings = shadowmap::printSettings(shadowmap::ShadowSettings{});
    settings.update(defaults_);
    const nlohmann::json& extras = scene_.lights[lights_[index].light].extras;
    if (extras.is_object() && extras.contains("shadow") && extras["shadow"].is_object())
        settings.update(extras["shadow"]);
    if (!settings.contains("polygon_offset")) {
        // No explicit offset: the one the plugin used (the variant's default).
        const engine::ShadowView* view = frameView(index);
        const glm::vec2 used = view ? shadowmap::usedSettings(*view).effectivePolygonOffset() : glm::vec2(0.0f);
        settings["polygon_offset"] = {shadowmap::jsonNumber(used.x), shadowmap::jsonNumber(used.y)};
    }
    return settings;
}

nlohmann::json ViewerState::savedShadow(int index) const {
    const int light = lights_[index].light;
    const nlohmann::json& extras = scene_.lights[light].extras;
    const nlohmann::json current =
        extras.is_object() && extras.contains("shadow") && extras["shadow"].is_object() ? extras["shadow"]
                                                                                        : nlohmann::json::object();
    return tools::savedShadow(defaults_, loaded_[light], current);
}

void ViewerState::set(int index, const std::string& key, const nlohmann::json& value) {
    if (index < 0 || index >= static_cast<int>(lights_.size())) return;
    shadowOf(index)[key] = value;
    dirty_ = true;
}

void ViewerState::cycleVariant() {
    if (selected_ < 0) return;
    set(selected_, "variant", nextChoice("variant", effective(selected_)["variant"].get<std::string>()));
}

void ViewerState::cycleResolution() {
    if (selected_ < 0) return;
    const std::vector<double>& steps = shadowmap::settingKey("resolution").steps;
    const double current = effective(selected_)["resolution"].get<double>();
    const auto next = std::upper_bound(steps.begin(), steps.end(), current);
    set(selected_, "resolution", static_cast<int>(next == steps.end() ? steps.front() : *next));
}

void ViewerState::cycleDepthFormat() {
    if (selected_ < 0) return;
    set(selected_, "depth_format", nextChoice("depth_format", effective(selected_)["depth_format"].get<std::string>()));
}

void ViewerState::toggleFilter() {
    if (selected_ < 0) return;
    const nlohmann::json current = effective(selected_);
    const engine::Light::Type type = scene_.lights[lights_[selected_].light].type;
    // The keys skip a filter the light's other settings refuse: pcss without a size, a
    // filter other than pcf, vsm or evsm with a filter_radius, vsm with lispsm or an infinite
    // far plane.
    const auto accepted = [&](const std::string& filter) {
        shadowmap::ShadowSettings settings = shadowmap::parseSettings(current, "engine-view", "filter");
        shadowmap::applySettings(settings, {{"filter", filter}}, "engine-view", "filter");
        try {
            shadowmap::checkFilterForType(settings, type, "engine-view", "filter");
            return true;
        } catch (const engine::InputError&) {
            return false;
        }
    };
    std::string filter = current["filter"].get<std::string>();
    do filter = nextChoice("filter", filter);
    while (!accepted(filter));  // ends: the hard filters need no size
    set(selected_, "filter", filter);
}

void ViewerState::cycleCascades() {
    if (selected_ < 0) return;
    const nlohmann::json current = effective(selected_)["cascades"];
    const shadowmap::SettingKey& key = shadowmap::settingKey("cascades");
    const auto next = current.is_number() ? std::upper_bound(key.steps.begin(), key.steps.end(), current.get<double>())
                                          : key.steps.begin();
    set(selected_, "cascades", next == key.steps.end() ? nlohmann::json(key.choices.front())
                                                        : nlohmann::json(static_cast<int>(*next)));
}

void ViewerState::toggleStable() {
    if (selected_ < 0) return;
    set(selected_, "stable", !effective(selected_)["stable"].get<bool>());
}

void ViewerState::addOffsetUnits(double delta) {
    if (selected_ < 0) return;
    const nlohmann::json offset = effective(selected_)["polygon_offset"];
    const double factor = offset.at(0).get<double>();
    const double units = std::max(offset.at(1).get<double>() + delta, 0.0);
    set(selected_, "polygon_offset", nlohmann::json::array({factor, units}));
}

void ViewerState::addDimming(double delta) {
    if (selected_ < 0) return;
    const shadowmap::SettingKey& range = shadowmap::settingKey("dimming");
    const double dimming =
        std::clamp(effective(selected_)["dimming"].get<double>() + delta, *range.minimum, *range.maximum);
    set(selected_, "dimming", std::round(dimming * 100.0) / 100.0);
}

std::string ViewerState::changeLightSize(bool grow) {
    if (selected_ < 0) return {};
    const ViewedLight& light = lights_[selected_];
    const nlohmann::json current = effective(selected_);
    const char* key = lightSizeKey(light.type);
    const double size = stepLightSize(current[key].get<double>(), light.type, grow);
    set(selected_, key, size);
    const std::string pcss = shadowmap::toString(shadowmap::Filter::Pcss);
    if (size > 0.0 || current["filter"] != pcss) return {};
    // pcss without a size is a setting the plugin refuses. Refusing the step instead would
    // leave 0 out of the keys' reach while pcss is on (and P goes from pcss to nearest, not
    // to pcf); pcf is the filter a point light's shadow is best served by, and the filter
    // every light starts with. A step up again does not bring pcss back: P does.
    const std::string pcf = shadowmap::toString(shadowmap::Filter::Pcf);
    set(selected_, "filter", pcf);
    return light.name + ": " + key + " 0 is a point light, which pcss cannot soften: filter " + pcss + " -> " + pcf;
}

void ViewerState::apply(engine::Renderer& renderer) {
    if (!dirty_) return;
    dirty_ = false;
    try {
        renderer.reloadSettings();
    } catch (const engine::InputError&) {
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) scene_.lights[i].extras = applied_[i];
        renderer.reloadSettings();
        throw;
    }
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) applied_[i] = scene_.lights[i].extras;
}

} // namespace engine_view
