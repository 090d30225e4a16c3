#pragma once
// Loads the plugins named by the engine config and owns them. Load order and checks follow
// plugins/include/engine_plugin/PluginAbi.h; every failure is one InputError naming the
// library file and the reason, and leaves nothing loaded from that library.
#include "engine/config/EngineConfig.h"
#include "engine/plugin/RenderPlugin.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace engine {

class PluginHost {
public:
    PluginHost();
    PluginHost(const PluginHost&) = delete;
    PluginHost& operator=(const PluginHost&) = delete;
    ~PluginHost();  // destroys every plugin object, then dlcloses, in reverse load order

    // Resolves `library` (a bare name, no '/') to <dir>/<library>.so in the first of
    // `searchDirs` that has it, loads and registers it.
    void load(const PluginConfig& plugin, const std::vector<std::filesystem::path>& searchDirs);
    void loadAll(const EngineConfig& config);

    std::vector<RenderPlugin*> renderPlugins() const;
    // The render plugins that the library of that name (as the config names it) registered.
    std::vector<RenderPlugin*> renderPlugins(const std::string& library) const;
    std::vector<std::string> loadedNames() const;

    // Where plugins are looked for: the config's dirs, then the build's plugin folder.
    static std::vector<std::filesystem::path> searchDirectories(const EngineConfig& config);

private:
    struct LoadedLibrary;
    std::vector<std::unique_ptr<LoadedLibrary>> libraries_;
};

} // namespace engine
