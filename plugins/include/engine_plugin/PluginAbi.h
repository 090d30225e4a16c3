#pragma once
// The one ABI header between the engine and its plugins.
//
// A plugin is a shared object that exports exactly one C entry point, ENGINE_PLUGIN_ENTRY,
// returning a static EnginePluginInfo. The host (engine/plugin/PluginHost) checks, in this
// order and with one clear error for each failure (as Corrade's PluginManager does):
//   dlopen(RTLD_NOW) -> entry symbol -> abiVersion -> interfaceId -> registerPlugin().
// registerPlugin receives the engine's PluginRegistry (a C++ object: engine and plugins are
// built by the same compiler against the same libengine, which the ABI version pins) and
// the plugin's settings as JSON text; it may throw to refuse (bad settings), and the host
// reports the exception text with the library name and unloads the library.
//
// Bump ENGINE_PLUGIN_ABI_VERSION on every change to this file or to the classes reachable
// from PluginRegistry (engine/plugin/RenderPlugin.h, engine/render/Frame.h, the graph).
#include <cstdint>

#define ENGINE_PLUGIN_ABI_VERSION 9u
#define ENGINE_PLUGIN_INTERFACE_ID "org.shadowengine.RenderPlugin/1.0"
#define ENGINE_PLUGIN_ENTRY engine_plugin_entry
#define ENGINE_PLUGIN_ENTRY_NAME "engine_plugin_entry"

namespace engine {
class PluginRegistry;
}

extern "C" {

struct EnginePluginInfo {
    std::uint32_t abiVersion;   // ENGINE_PLUGIN_ABI_VERSION the plugin was built with
    const char* interfaceId;    // ENGINE_PLUGIN_INTERFACE_ID the plugin was built with
    const char* name;           // human-readable, for messages and stats
    // Registers the plugin's objects. settingsJson is a JSON object (never null).
    void (*registerPlugin)(engine::PluginRegistry* registry, const char* settingsJson);
};

typedef const EnginePluginInfo* (*EnginePluginEntryFunction)();

}  // extern "C"

// Use in exactly one source file of a plugin:
//   ENGINE_DECLARE_PLUGIN("shadowmap_plugin", &registerShadowPlugin)
#define ENGINE_DECLARE_PLUGIN(pluginName, registerFunction)                                 \
    extern "C" __attribute__((visibility("default"))) const EnginePluginInfo*            \
    ENGINE_PLUGIN_ENTRY() {                                                                \
        static const EnginePluginInfo info{ENGINE_PLUGIN_ABI_VERSION,                      \
                                           ENGINE_PLUGIN_INTERFACE_ID, pluginName,         \
                                           registerFunction};                              \
        return &info;                                                                      \
    }
