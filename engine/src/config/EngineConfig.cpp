#include "engine/config/EngineConfig.h"

#include "engine/util/Error.h"
#include "engine/util/InputFile.h"
#include "engine/util/InstallLayout.h"
#include "engine/util/JsonRead.h"

#include <algorithm>
#include <cstdint>

namespace engine {

namespace {

PluginConfig parsePlugin(const nlohmann::json& entry, const std::string& file,
                         const std::string& where) {
    json::requireKnownKeys(entry, {"library", "settings"}, file, where);
    if (!entry.contains("library")) throwInputError(file, where, "missing \"library\"");
    PluginConfig plugin;
    plugin.library = json::readString(entry["library"], file, where + ".library");
    // A bare name only: the host decides the folder, never the config or the current dir.
    if (plugin.library.empty() || plugin.library.find('/') != std::string::npos ||
        plugin.library == "." || plugin.library == "..")
        throwInputError(file, where + ".library",
                        "\"" + plugin.library + "\" must be a bare library name without '/'");
    if (entry.contains("settings")) {
        if (!entry["settings"].is_object())
            throwInputError(file, where + ".settings", "must be a JSON object");
        plugin.settings = entry["settings"];
    }
    return plugin;
}

// true, false, or "auto" (left unset: decideSwitches decides for the renderer).
void readSwitch(const nlohmann::json& node, const char* key, const std::string& file,
                std::optional<bool>& value) {
    if (!node.contains(key)) return;
    const std::string where = std::string("renderer.") + key;
    const nlohmann::json& entry = node[key];
    if (entry.is_string() && entry.get<std::string>() == "auto") value.reset();
    else if (entry.is_boolean()) value = entry.get<bool>();
    else throwInputError(file, where, "must be true, false or \"auto\", not " + entry.dump());
}

RendererConfig parseRenderer(const nlohmann::json& node, const std::string& file) {
    json::requireKnownKeys(node,
                           {"ambient", "clear_color", "exposure", "tone_mapping", "msaa", "shade_cache", "light_footprints", "unrolled_light_sum", "clustered_lights",
                            "check_gl_errors"},
                           file, "renderer");
    RendererConfig renderer;
    if (node.contains("ambient"))
        renderer.ambient = glm::vec3(json::readVec3(node["ambient"], file, "renderer.ambient"));
    if (node.contains("clear_color"))
        renderer.clearColor =
            glm::vec3(json::readVec3(node["clear_color"], file, "renderer.clear_color"));
    if (node.contains("exposure")) {
        const double exposure = json::readNumber(node["exposure"], file, "renderer.exposure");
        if (!(exposure > 0.0) || exposure > 1e30)
            throwInputError(file, "renderer.exposure", "must be a positive number, not " + node["exposure"].dump());
        renderer.exposure = static_cast<float>(exposure);
    }
    if (node.contains("tone_mapping")) {
        const std::string mapping = json::readString(node["tone_mapping"], file, "renderer.tone_mapping");
        if (mapping == "none") renderer.toneMapping = RendererConfig::ToneMapping::None;
        else if (mapping == "pbr_neutral") renderer.toneMapping = RendererConfig::ToneMapping::PbrNeutral;
        else throwInputError(file, "renderer.tone_mapping", "\"" + mapping + "\" is not \"none\" or \"pbr_neutral\"");
    }
    if (node.contains("msaa")) {
        const nlohmann::json& entry = node["msaa"];
        // Read wide: a huge integer must not wrap around to an accepted count.
        if (!entry.is_number_integer() || entry.get<std::int64_t>() != static_cast<int>(entry.get<std::int64_t>()) ||
            !isMsaaSampleCount(static_cast<int>(entry.get<std::int64_t>())))
            throwInputError(file, "renderer.msaa", "must be " + msaaSampleCountsText() + " (samples per pixel), not " + entry.dump());
        renderer.msaa = static_cast<int>(entry.get<std::int64_t>());
    }
    readSwitch(node, "shade_cache", file, renderer.shadeCache);
    // Asked for both, the user would silently get one: the shade cache cannot serve a
    // multisampled lit pass (RendererConfig::msaa).
    if (renderer.msaa > 1 && renderer.shadeCache.value_or(false))
        throwInputError(file, "renderer.shade_cache",
                        "true needs renderer.msaa 1 (a multisampled image has no shade cache); set it to \"auto\" or false");
    readSwitch(node, "light_footprints", file, renderer.lightFootprints);
    readSwitch(node, "unrolled_light_sum", file, renderer.unrolledLightSum);
    readSwitch(node, "clustered_lights", file, renderer.clusteredLights);
    if (node.contains("check_gl_errors"))
        renderer.checkGlErrors = json::readBool(node["check_gl_errors"], file, "renderer.check_gl_errors");
    return renderer;
}

} // namespace

bool isSoftwareRasterizer(std::string_view glRenderer) {
    for (const std::string_view name : {"llvmpipe", "softpipe", "swrast"})
        if (glRenderer.find(name) != std::string_view::npos) return true;
    return false;
}

std::string msaaSampleCountsText() {
    std::string text;
    for (std::size_t i = 0; i < kMsaaSampleCounts.size(); ++i)
        text += (i == 0 ? "" : i + 1 == kMsaaSampleCounts.size() ? " or " : ", ") + std::to_string(kMsaaSampleCounts[i]);
    return text;
}

bool isMsaaSampleCount(int samples) {
    return std::find(kMsaaSampleCounts.begin(), kMsaaSampleCounts.end(), samples) != kMsaaSampleCounts.end();
}

RendererSwitches decideSwitches(const RendererConfig& config, std::string_view glRenderer) {
    const bool software = isSoftwareRasterizer(glRenderer);
    return {config.msaa == 1 && config.shadeCache.value_or(software), config.lightFootprints.value_or(software),
            config.unrolledLightSum.value_or(software)};
}

EngineConfig parseEngineConfig(const std::string& jsonText, const std::filesystem::path& path) {
    const std::string file = path.string();
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(jsonText);
    } catch (const nlohmann::json::parse_error& error) {
        throwInputError(file, "", std::string("not valid JSON: ") + error.what());
    }
    json::requireKnownKeys(root, {"plugins", "plugin_dirs", "renderer"}, file, "");

    EngineConfig config;
    config.sourcePath = path;
    const std::filesystem::path base = path.has_parent_path() ? path.parent_path() : ".";
    if (root.contains("plugin_dirs")) {
        if (!root["plugin_dirs"].is_array()) throwInputError(file, "plugin_dirs", "must be an array");
        for (std::size_t i = 0; i < root["plugin_dirs"].size(); ++i) {
            std::filesystem::path dir = json::readString(
                root["plugin_dirs"][i], file, "plugin_dirs[" + std::to_string(i) + "]");
            config.pluginDirs.push_back(dir.is_absolute() ? dir : base / dir);
        }
    }
    if (root.contains("plugins")) {
        if (!root["plugins"].is_array()) throwInputError(file, "plugins", "must be an array");
        for (std::size_t i = 0; i < root["plugins"].size(); ++i)
            config.plugins.push_back(
                parsePlugin(root["plugins"][i], file, "plugins[" + std::to_string(i) + "]"));
    }
    if (root.contains("renderer")) config.renderer = parseRenderer(root["renderer"], file);
    return config;
}

EngineConfig loadEngineConfig(const std::filesystem::path& path) {
    return parseEngineConfig(readWholeFile(path, "the engine config"), path);
}

std::vector<std::filesystem::path> defaultEngineConfigCandidates() {
    std::vector<std::filesystem::path> candidates{std::filesystem::path("content") / "engine.json"};
    if (const auto sourceContent = buildTreeDataDir()) candidates.push_back(*sourceContent / "engine.json");
    candidates.push_back(installedDataDir() / "engine.json");
    return candidates;
}

std::filesystem::path findDefaultEngineConfig() { return firstExistingEngineConfig(defaultEngineConfigCandidates()); }

std::filesystem::path firstExistingEngineConfig(const std::vector<std::filesystem::path>& candidates) {
    std::string tried;
    for (const auto& candidate : candidates) {
        std::error_code error;
        if (std::filesystem::is_regular_file(candidate, error)) return candidate;
        tried += (tried.empty() ? "" : ", ") + candidate.string();
    }
    throwInputError("", "engine config", "no default engine.json found (tried " + tried + ")");
}

} // namespace engine
