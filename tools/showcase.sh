#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, renders the showcase scene
# headless (EGL, Mesa llvmpipe) and prints per-pass and per-light times and shadow errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh build
mkdir -p out
build/bin/engine-render --config content/engine.json --scene content/scenes/showcase.gltf \
  --out out/showcase.png --width 1280 --height 720 --frames 5 \
  --truth --set shadowmap_plugin.cache_maps=false \
  --stats out/showcase-stats.json --graph-dot out/showcase-graph.dot "$@"
echo "wrote out/showcase.png, out/showcase-stats.json, out/showcase-graph.dot"
