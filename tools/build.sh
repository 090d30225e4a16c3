#!/usr/bin/env bash
# Configures and builds one build folder: tools/build.sh [BUILD_DIR] [extra cmake args...]
# Default: build/ in Release. Uses every core, and ccache where the machine has it (a
# machine that keeps its cache rebuilds only what changed; a fresh one gains nothing).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
mkdir -p "$build_dir"
launcher=()
if command -v ccache > /dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" > "$build_dir/configure.log" 2>&1 \
  || { cat "$build_dir/configure.log"; exit 1; }
cmake --build "$build_dir" -j"$(nproc)"
