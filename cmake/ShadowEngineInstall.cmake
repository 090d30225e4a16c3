# `cmake --install`, find_package(ShadowEngine), pkg-config shadow-engine and `cpack -G DEB`.
# The layout is in cmake/InstallLayout.cmake; docs/installing.md is the
# user's view of both.
include(CMakePackageConfigHelpers)

# Every program a user runs (the manual's tools); the build's own helpers (microbenchmarks,
# fuzzers, test programs) stay out. tests/install/check_tools.sh runs each installed one.
set(ENGINE_INSTALLED_TOOLS engine-render engine-view shadowmap-bench shadowmap-stress shadowmap-tune soak)

# Programs and the plugin find libengine through a RUNPATH relative to themselves ($ORIGIN),
# so a relocated install (staged, DESTDIR, an unpacked .deb) runs as it is. In the .deb it
# points at /usr/lib/<multiarch>, where the linker looks anyway.
file(RELATIVE_PATH _bin_to_lib ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR})
file(RELATIVE_PATH _plugin_to_lib ${CMAKE_INSTALL_PREFIX}/${ENGINE_INSTALL_PLUGIN_DIR}
     ${CMAKE_INSTALL_FULL_LIBDIR})
set_target_properties(${ENGINE_INSTALLED_TOOLS} PROPERTIES INSTALL_RPATH "$ORIGIN/${_bin_to_lib}")
set_target_properties(shadowmap_plugin PROPERTIES INSTALL_RPATH "$ORIGIN/${_plugin_to_lib}")

install(TARGETS engine shadowmap_settings EXPORT ShadowEngineTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS shadowmap_plugin LIBRARY DESTINATION ${ENGINE_INSTALL_PLUGIN_DIR} COMPONENT runtime)
install(TARGETS ${ENGINE_INSTALLED_TOOLS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/ ${PROJECT_SOURCE_DIR}/plugins/include/
                  ${PROJECT_SOURCE_DIR}/shadowmap_plugin/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)

# content/ as it is (engine.json beside scenes/), so a config's relative paths and the
# tools' defaults mean the same in a checkout and in an install.
install(FILES ${PROJECT_SOURCE_DIR}/content/engine.json ${PROJECT_SOURCE_DIR}/content/engine-unshadowed.json
  DESTINATION ${ENGINE_INSTALL_DATA_DIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/content/scenes DESTINATION ${ENGINE_INSTALL_DATA_DIR}
  COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs COMPONENT runtime)

# find_package(ShadowEngine): ShadowEngine::engine and ShadowEngine::shadowmap_settings.
install(EXPORT ShadowEngineTargets NAMESPACE ShadowEngine:: DESTINATION ${ENGINE_INSTALL_CMAKE_DIR}
  COMPONENT development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ShadowEngineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ShadowEngineConfig.cmake INSTALL_DESTINATION ${ENGINE_INSTALL_CMAKE_DIR}
  PATH_VARS ENGINE_INSTALL_PLUGIN_DIR ENGINE_INSTALL_DATA_DIR)
# The engine has no stable ABI yet: a consumer built against 0.1 needs 0.1.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ShadowEngineConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ShadowEngineConfig.cmake
              ${PROJECT_BINARY_DIR}/ShadowEngineConfigVersion.cmake
  DESTINATION ${ENGINE_INSTALL_CMAKE_DIR} COMPONENT development)

# pkg-config: prefix from the .pc file's own folder, relocatable like the rest.
file(RELATIVE_PATH ENGINE_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" ENGINE_PC_TO_PREFIX "${ENGINE_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/shadow-engine.pc.in ${PROJECT_BINARY_DIR}/shadow-engine.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/shadow-engine.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
  COMPONENT development)

include(${PROJECT_SOURCE_DIR}/cmake/ShadowEngineDeb.cmake)
