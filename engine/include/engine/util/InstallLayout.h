#pragma once
// Where an installed engine keeps its plugins and data, found from the libengine.so this
// process loaded (dladdr), not from a path fixed at build time: a staged install, a DESTDIR
// tree or an unpacked .deb works wherever it sits, as long as the folders keep their places
// relative to each other (GNUInstallDirs: lib[/<multiarch>], share).
#include <filesystem>
#include <optional>

namespace engine {

// The folder holding the libengine.so that is running.
std::filesystem::path engineLibraryDir();

// <libdir>/shadow-engine/plugins: the installed plugins (a private folder of the package, as
// Debian keeps modules only its own program loads, so they stay out of the linker's path).
std::filesystem::path installedPluginDir();

// <datadir>/shadow-engine: the default configs (engine.json) and the showcase scenes.
std::filesystem::path installedDataDir();

// The build tree's plugin folder, only while libengine runs from that build tree: a
// libengine installed from a package must never pick plugins out of whatever build folder
// its builder had at that path.
std::optional<std::filesystem::path> buildTreePluginDir();

// The source tree's content/ folder (default configs, showcase scenes), under the same
// condition: what installedDataDir() is to an install.
std::optional<std::filesystem::path> buildTreeDataDir();

} // namespace engine
