#include "engine/plugin/PluginHost.h"

#include "engine/util/Error.h"
#include "engine/util/InstallLayout.h"

#include <engine_plugin/PluginAbi.h>

#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace engine {

// One dlopen'ed library and what it registered. The registry (and so every object whose
// code lives in the library) is destroyed before the handle is closed.
struct PluginHost::LoadedLibrary {
    std::filesystem::path path;
    std::string library;  // as the config names it
    std::string name;
    void* handle = nullptr;
    PluginRegistry registry;

    ~LoadedLibrary() {
        registry.renderPlugins().clear();
        if (handle) dlclose(handle);
    }
};

namespace {

std::string lastDlError() {
    const char* message = dlerror();
    return message ? message : "unknown dynamic loader error";
}

bool isRegularFile(const std::filesystem::path& path) {
    struct stat info{};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::filesystem::path resolveLibrary(const std::string& library,
                                     const std::vector<std::filesystem::path>& searchDirs) {
    std::string searched;
    for (const auto& dir : searchDirs) {
        const std::filesystem::path candidate = dir / (library + ".so");
        if (isRegularFile(candidate)) return std::filesystem::canonical(candidate);
        searched += (searched.empty() ? "" : ", ") + dir.string();
    }
    throwInputError("", "plugin \"" + library + "\"",
                    "library " + library + ".so not found in the plugin directories (" +
                        (searched.empty() ? "none configured" : searched) + ")");
}

} // namespace

PluginHost::PluginHost() = default;

PluginHost::~PluginHost() {
    while (!libraries_.empty()) libraries_.pop_back();  // reverse load order
}

std::vector<std::filesystem::path> PluginHost::searchDirectories(const EngineConfig& config) {
    std::vector<std::filesystem::path> dirs = config.pluginDirs;
    for (const auto& dir : environmentPluginDirs()) dirs.push_back(dir);
    dirs.push_back(installedPluginDir());
    if (const auto buildDir = buildTreePluginDir()) dirs.push_back(*buildDir);
    // A folder named twice (ENGINE_PLUGIN_PATH set to the installed one) is searched once,
    // at its first place, so the list in a "not found" error has no repeats.
    std::vector<std::filesystem::path> unique;
    for (const auto& dir : dirs)
        if (std::find(unique.begin(), unique.end(), dir.lexically_normal()) == unique.end())
            unique.push_back(dir.lexically_normal());
    return unique;
}

std::vector<std::filesystem::path> PluginHost::environmentPluginDirs() {
    std::vector<std::filesystem::path> dirs;
    const char* value = std::getenv("ENGINE_PLUGIN_PATH");
    if (!value) return dirs;
    // Colon-separated like PATH; empty entries mean nothing (not the current folder, which
    // would make the loaded code depend on where the user happens to stand).
    const std::string list = value;
    std::size_t begin = 0;
    while (begin <= list.size()) {
        const std::size_t end = std::min(list.find(':', begin), list.size());
        if (end > begin) dirs.emplace_back(list.substr(begin, end - begin));
        begin = end + 1;
    }
    return dirs;
}

void PluginHost::load(const PluginConfig& plugin,
                      const std::vector<std::filesystem::path>& searchDirs) {
    const std::filesystem::path path = resolveLibrary(plugin.library, searchDirs);
    const std::string file = path.string();

    auto library = std::make_unique<LoadedLibrary>();
    library->path = path;
    library->library = plugin.library;
    dlerror();
    // RTLD_NOW: an unresolved symbol fails here, not at first call in the middle of a frame.
    library->handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library->handle) throwInputError(file, "", "cannot load plugin: " + lastDlError());

    auto entry = reinterpret_cast<EnginePluginEntryFunction>(
        dlsym(library->handle, ENGINE_PLUGIN_ENTRY_NAME));
    if (!entry)
        throwInputError(file, "", std::string("not an engine plugin: no entry point ") +
                                      ENGINE_PLUGIN_ENTRY_NAME + "()");
    const EnginePluginInfo* info = entry();
    if (!info) throwInputError(file, "", "the entry point returned no plugin info");
    if (info->abiVersion != ENGINE_PLUGIN_ABI_VERSION)
        throwInputError(file, "", "plugin ABI version " + std::to_string(info->abiVersion) +
                                      ", the engine needs " +
                                      std::to_string(ENGINE_PLUGIN_ABI_VERSION) + ": rebuild it");
    if (!info->interfaceId || std::strcmp(info->interfaceId, ENGINE_PLUGIN_INTERFACE_ID) != 0)
        throwInputError(file, "", std::string("plugin interface \"") +
                                      (info->interfaceId ? info->interfaceId : "(null)") +
                                      "\", the engine needs \"" ENGINE_PLUGIN_INTERFACE_ID "\"");
    if (!info->registerPlugin) throwInputError(file, "", "the plugin has no register function");
    library->name = info->name ? info->name : plugin.library;

    const std::string settings = plugin.settings.is_null() ? "{}" : plugin.settings.dump();
    try {
        info->registerPlugin(&library->registry, settings.c_str());
    } catch (const std::exception& error) {
        throwInputError(file, "plugin \"" + library->name + "\"",
                        std::string("registration failed: ") + error.what());
    } catch (...) {
        throwInputError(file, "plugin \"" + library->name + "\"",
                        "registration failed with an unknown exception");
    }
    libraries_.push_back(std::move(library));
}

void PluginHost::loadAll(const EngineConfig& config) {
    const auto dirs = searchDirectories(config);
    for (const auto& plugin : config.plugins) {
        try {
            load(plugin, dirs);
        } catch (const InputError& error) {
            // Prefix the config file so the user knows where the plugin was named.
            throw InputError(config.sourcePath.string() + ": " + error.what());
        }
    }
}

std::vector<RenderPlugin*> PluginHost::renderPlugins() const {
    std::vector<RenderPlugin*> out;
    for (const auto& library : libraries_)
        for (const auto& plugin : library->registry.renderPlugins()) out.push_back(plugin.get());
    return out;
}

std::vector<RenderPlugin*> PluginHost::renderPlugins(const std::string& library) const {
    std::vector<RenderPlugin*> out;
    for (const auto& loaded : libraries_)
        if (loaded->library == library)
            for (const auto& plugin : loaded->registry.renderPlugins()) out.push_back(plugin.get());
    return out;
}

std::vector<std::filesystem::path> PluginHost::loadedFiles() const {
    std::vector<std::filesystem::path> out;
    for (const auto& library : libraries_) out.push_back(library->path);
    return out;
}

std::vector<std::string> PluginHost::loadedNames() const {
    std::vector<std::string> out;
    for (const auto& library : libraries_) out.push_back(library->name);
    return out;
}

} // namespace engine
