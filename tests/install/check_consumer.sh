#!/usr/bin/env bash
# Installs the build into a staged prefix, builds tests/install/consumer against it with
# find_package(ShadowEngine) and runs it from a folder that is neither the source nor the
# build tree, so the default config and the plugin can only come from the install; then
# once more without the installed plugin, which must fail naming only the install's folder.
#   check_consumer.sh BUILD_DIR WORK_DIR CXX_COMPILER BUILD_TYPE "EXTRA_CXX_FLAGS"
set -euo pipefail
build=$1 work=$2 cxx=$3 build_type=$4 extra_flags=$5
consumer_src=$(dirname "$(readlink -f "$0")")/consumer
prefix=$work/staged-install
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$work"
mkdir -p "$work/run"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }

# The sanitizer flags are the build's choice, not the package's: a consumer of an ASan
# libengine must itself be built with ASan (its runtime has to come first), so they are
# passed here instead of being exported in ShadowEngineTargets.cmake.
cmake -S "$consumer_src" -B "$work/consumer-build" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$build_type" \
      -DCMAKE_CXX_FLAGS="$extra_flags" -DCMAKE_EXE_LINKER_FLAGS="$extra_flags" \
      > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configuring the consumer"; }
cmake --build "$work/consumer-build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "building the consumer"; }

# pkg-config reads the same install (relocatable: the prefix comes from the .pc's folder).
pc=$(find "$prefix" -name shadow-engine.pc)
[[ -n $pc ]] || fail "no shadow-engine.pc installed"
plugindir=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --variable=plugindir shadow-engine)
[[ -f $plugindir/shadowmap_plugin.so ]] || fail "pkg-config's plugindir $plugindir has no shadowmap_plugin.so"
libs=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --libs shadow-engine)
[[ -e $(sed -n 's/^-L\([^ ]*\) .*/\1/p' <<<"$libs")/libengine.so ]] || fail "pkg-config --libs ($libs) names no libengine.so"

cd "$work/run"
env -u ENGINE_PLUGIN_PATH "$work/consumer-build/consumer" "$prefix"

# Without the installed plugin the error lists the folders tried, and an installed engine
# never falls back to the build tree it was built in (that plugin exists, and must not load).
plugin=$(find "$prefix" -name shadowmap_plugin.so)
mv "$plugin" "$work/moved_plugin.so"
if message=$(env -u ENGINE_PLUGIN_PATH "$work/consumer-build/consumer" "$prefix" 2>&1); then
  fail "the consumer ran without the installed plugin: $message"
fi
echo "$message"
grep -qF "not found in the plugin directories ($(dirname "$plugin"))" <<<"$message" \
  || fail "the error does not list exactly the installed plugin folder"
[[ -f $build/plugins/shadowmap_plugin.so ]] || fail "the build tree has no plugin: the check above proves nothing"
echo "install OK"

