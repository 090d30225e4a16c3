# `cpack -G DEB` in the build folder: one package, shadow-engine_<version>_<arch>.deb, with
# everything `cmake --install` puts down. Configure with -DCMAKE_INSTALL_PREFIX=/usr for the
# Debian layout (lib/<multiarch>, no RPATH).
set(CPACK_PACKAGE_NAME shadow-engine)
set(CPACK_PACKAGE_VENDOR "shadow-engine developers")
set(CPACK_PACKAGE_CONTACT "shadow-engine developers <shadow-engine@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "scene-graph engine with a shadow-mapping plugin, headless on EGL/llvmpipe")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# Libraries the programs link: found by dpkg-shlibdeps (dpkg-dev, in build-essential) from
# the binaries, so the list follows what is really linked (epoxy, glfw, tinygltf, embree...).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libengine.so.0 is ours: tell dpkg-shlibdeps where it is instead of asking the system.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CMAKE_INSTALL_LIBDIR})
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# What no ELF file names, so shlibdeps cannot see it: epoxy dlopens libEGL/libGL at run time,
# and libEGL needs Mesa's EGL vendor and llvmpipe (the DRI driver) to render headless.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1, libegl-mesa0, libgl1-mesa-dri")
# Building against the installed headers and CMake package needs their headers too.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libglm-dev, nlohmann-json3-dev, libepoxy-dev, pkg-config, cmake")
include(CPack)
