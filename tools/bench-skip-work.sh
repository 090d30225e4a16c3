#!/usr/bin/env bash
# What skipping work buys (issue: cached maps, culling). For the showcase and Debian's
# 2CylinderEngine.glb (one spot key light), at 1280x720 with 2048 maps, in one run:
# the median frame time with no shadows, with a static light (its map is cached), and with
# an orbiting light (its map re-rendered every frame), and the ratios between them.
# Usage: tools/bench-skip-work.sh [FRAMES]   (build first: tools/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-20}
render=build/bin/engine-render
engine_glb=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median_ms() {  # prints the median frame time engine-render reports
  "$render" --out "$out/frame.png" --width 1280 --height 720 --frames "$frames" "$@" |
    sed -n 's/.*median frame \([0-9.]*\) ms.*/\1/p'
}

row() {  # name, unshadowed args..., then "--" static args..., then "--" orbit light
  local name=$1 scene=$2 light=$3; shift 3
  local none static orbit
  none=$(median_ms --config content/engine-unshadowed.json --scene "$scene" "$@")
  static=$(median_ms --config content/engine.json --scene "$scene" "$@")
  orbit=$(median_ms --config content/engine.json --scene "$scene" "$@" --orbit-light "$light")
  awk -v n="$name" -v a="$none" -v b="$static" -v c="$orbit" 'BEGIN {
    printf "%-16s %10.1f %10.1f %10.1f %12.3f %12.3f\n", n, a, b, c, b / a, c / a }'
}

echo "median frame ms over $frames frames, 1280x720, llvmpipe ($(nproc) cores)"
printf "%-16s %10s %10s %10s %12s %12s\n" scene unshadowed static orbiting static/none orbit/none
row showcase content/scenes/showcase.gltf spot_light
if [ -f "$engine_glb" ]; then
  row 2CylinderEngine "$engine_glb" key_light --key-light spot
else
  echo "2CylinderEngine.glb not found (apt-get install assimp-testmodels)"
fi
