# Where an install puts things (GNUInstallDirs), decided before the targets so libengine can
# be told where its plugins and data sit relative to its own folder (util/InstallLayout.h).
#   bin/                                   the tools (ENGINE_INSTALLED_TOOLS, ShadowEngineInstall.cmake)
#   lib[/<multiarch>]/libengine.so*        the engine (+ libshadowmap_settings.a, CMake files)
#   lib[/<multiarch>]/shadow-engine/plugins/shadowmap_plugin.so
#                                          private modules only the engine dlopens: out of the
#                                          linker's path, beside the arch-specific library
#   include/engine, engine_plugin, shadowmap      public headers
#   share/shadow-engine/                   engine.json, engine-unshadowed.json, scenes/
#   share/doc/shadow-engine/               README.md, docs/
# Shaders are compiled into the libraries (cmake/EmbedText.cmake): none are installed.
set(CMAKE_INSTALL_DOCDIR share/doc/shadow-engine CACHE PATH "documentation (README, docs/)")
include(GNUInstallDirs)

set(ENGINE_INSTALL_PLUGIN_DIR ${CMAKE_INSTALL_LIBDIR}/shadow-engine/plugins)
set(ENGINE_INSTALL_DATA_DIR ${CMAKE_INSTALL_DATADIR}/shadow-engine)
set(ENGINE_INSTALL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ShadowEngine)

# Relative, so the install can move (staged installs, DESTDIR, an unpacked .deb).
file(RELATIVE_PATH ENGINE_LIB_TO_PLUGIN_DIR ${CMAKE_INSTALL_FULL_LIBDIR}
     ${CMAKE_INSTALL_PREFIX}/${ENGINE_INSTALL_PLUGIN_DIR})
file(RELATIVE_PATH ENGINE_LIB_TO_DATA_DIR ${CMAKE_INSTALL_FULL_LIBDIR}
     ${CMAKE_INSTALL_PREFIX}/${ENGINE_INSTALL_DATA_DIR})
