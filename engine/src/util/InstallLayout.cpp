#include "engine/util/InstallLayout.h"

#include <dlfcn.h>

#include <system_error>

// Set by engine/CMakeLists.txt from GNUInstallDirs (relative to the installed libdir), and
// the build tree's own folders.
#ifndef ENGINE_LIB_TO_PLUGIN_DIR
#error "ENGINE_LIB_TO_PLUGIN_DIR must be defined by the build"
#endif

namespace engine {

std::filesystem::path engineLibraryDir() {
    Dl_info info{};
    // Any function of libengine names the file it was loaded from.
    if (dladdr(reinterpret_cast<const void*>(&engineLibraryDir), &info) == 0 || !info.dli_fname)
        return {};
    std::error_code error;
    const auto library = std::filesystem::canonical(info.dli_fname, error);
    return error ? std::filesystem::path(info.dli_fname).parent_path() : library.parent_path();
}

std::filesystem::path installedPluginDir() {
    return (engineLibraryDir() / ENGINE_LIB_TO_PLUGIN_DIR).lexically_normal();
}

std::filesystem::path installedDataDir() {
    return (engineLibraryDir() / ENGINE_LIB_TO_DATA_DIR).lexically_normal();
}

namespace {

bool runningFromBuildTree() {
    std::error_code error;
    return std::filesystem::equivalent(engineLibraryDir(), ENGINE_BUILD_LIBRARY_DIR, error) && !error;
}

} // namespace

std::optional<std::filesystem::path> buildTreePluginDir() {
    if (!runningFromBuildTree()) return std::nullopt;
    return std::filesystem::path(ENGINE_BUILD_PLUGIN_DIR);
}

std::optional<std::filesystem::path> buildTreeDataDir() {
    if (!runningFromBuildTree()) return std::nullopt;
    return std::filesystem::path(ENGINE_BUILD_DATA_DIR);
}

} // namespace engine
