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
    // The file each loaded library came from (canonical), in load order.
    std::vector<std::filesystem::path> loadedFiles() const;

    // Where plugins are looked for, first match wins (docs/installing.md):
    //   1. the config's plugin_dirs (a relative one is relative to the config file);
    //   2. ENGINE_PLUGIN_PATH, colon-separated, in its order;
    //   3. the installed plugin folder, <libdir>/shadow-engine/plugins beside the running
    //      libengine.so (util/InstallLayout.h);
    //   4. the build tree's plugin folder, only while libengine runs from that build tree.
    // A plugin found nowhere is an error listing every folder of this list.
    static std::vector<std::filesystem::path> searchDirectories(const EngineConfig& config);
    // Step 2 alone: ENGINE_PLUGIN_PATH split at ':', empty entries dropped.
    static std::vector<std::filesystem::path> environmentPluginDirs();

private:
    struct LoadedLibrary;
    std::vector<std::unique_ptr<LoadedLibrary>> libraries_;
};

} // namespace engine
