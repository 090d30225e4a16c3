#!/usr/bin/env bash
# Builds examples/ the two ways docs/installing.md tells a user to build on an installed
# engine, against a staged install of this build, and runs what each built from a folder
# outside the source and build trees (ENGINE_PLUGIN_PATH unset):
#   1. examples/ as a project of its own: cmake -S examples -DCMAKE_PREFIX_PATH=PREFIX, then
#      render_one_frame with the example plugin and the installed shadow plugin, checked by
#      examples/test_examples.sh (as the in-tree Examples test checks the in-tree build);
#   2. render_one_frame/main.cpp compiled by the documented pkg-config line, which must give
#      a program that finds libengine.so.0 by itself (no LD_LIBRARY_PATH).
#   check_examples.sh SOURCE_DIR BUILD_DIR WORK_DIR CXX_COMPILER BUILD_TYPE "EXTRA_CXX_FLAGS"
set -euo pipefail
source_dir=$1 build=$2 work=$3 cxx=$4 build_type=$5 extra_flags=$6
prefix=$work/staged-install
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
scene=$prefix/share/shadow-engine/scenes/showcase.gltf
[[ -f $scene ]] || fail "the install has no $scene"
run=$(mktemp -d)
trap 'rm -rf "$run"' EXIT
unset ENGINE_PLUGIN_PATH LD_LIBRARY_PATH

# 1. CMake. The sanitizer flags are the build's choice, not the package's (check_consumer.sh
# says why); a plain build passes none.
cmake -S "$source_dir/examples" -B "$work/examples-build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$build_type" \
      -DCMAKE_CXX_FLAGS="$extra_flags" -DCMAKE_EXE_LINKER_FLAGS="$extra_flags" \
      -DCMAKE_MODULE_LINKER_FLAGS="$extra_flags" \
      > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configuring examples/ on its own"; }
cmake --build "$work/examples-build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building examples/ on its own"; }
# It must have linked the staged engine, not the build tree's.
ldd "$work/examples-build/render_one_frame" > "$work/ldd.txt"
grep -qF "$prefix/" "$work/ldd.txt" || { cat "$work/ldd.txt"; fail "the standalone render_one_frame does not load the staged libengine"; }
(cd "$run" && bash "$source_dir/examples/test_examples.sh" "$work/examples-build/render_one_frame" \
   "$work/examples-build/example_plugins" "$scene" "$run/cmake") || fail "the standalone CMake build of examples/"

# 2. pkg-config: the line docs/installing.md gives, with the sanitizer flags added.
export PKG_CONFIG_PATH
PKG_CONFIG_PATH=$(dirname "$(find "$prefix" -name shadow-engine.pc)")
# shellcheck disable=SC2046,SC2086  # word splitting of pkg-config's flags is intended
"$cxx" -std=c++20 $extra_flags "$source_dir/examples/render_one_frame/main.cpp" -o "$work/render_one_frame_pc" \
       $(pkg-config --cflags --libs shadow-engine) \
       -Wl,-rpath,"$(pkg-config --variable=libdir shadow-engine)" \
       > "$work/pkg-config-build.log" 2>&1 || { cat "$work/pkg-config-build.log"; fail "the pkg-config compile line"; }
ldd "$work/render_one_frame_pc" > "$work/ldd_pc.txt"
grep -q 'libengine.so.0 => .*/staged-install/' "$work/ldd_pc.txt" \
  || { cat "$work/ldd_pc.txt"; fail "the pkg-config build does not find the staged libengine.so.0 by itself"; }
# The installed config and the installed shadow plugin, found by the engine with no path given.
config=$prefix/share/shadow-engine/engine.json
(cd "$run" && "$work/render_one_frame_pc" "$config" "$scene" "$run/pc.png") > "$work/pc_run.txt" \
  || { cat "$work/pc_run.txt"; fail "the pkg-config build of render_one_frame exited $?"; }
cat "$work/pc_run.txt"
[[ -s $run/pc.png ]] || fail "the pkg-config build wrote no image"
grep -Eq '^light sun +standard$' "$work/pc_run.txt" || fail "the pkg-config build rendered no shadow map for the sun"
echo "examples OK against the install (CMake and pkg-config)"
