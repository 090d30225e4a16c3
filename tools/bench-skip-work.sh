#!/usr/bin/env bash
# What skipping work buys (cached maps, culling, shade cache, light footprints). For the
# showcase, the lamps scene (four narrow lamps: lookups limited to each lamp's footprint)
# and Debian's 2CylinderEngine.glb (one spot key light), at 1280x720 with 2048 maps, in one
# run: the median frame time with no shadows, with a static light (its map cached; with a
# still camera the lit pass also reuses every light's shade), with an orbiting light (its
# map and shade redone every frame), and the same with the camera orbiting (maps cached,
# shade recomputed every frame); the ratios between them, and the targets they must meet:
# static <= 1.05 x unshadowed, orbiting <= unshadowed + one depth pass (the orbiting
# light's median depth-pass time, printed as "depth").
# Usage: tools/bench-skip-work.sh [FRAMES]   (build first: tools/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-30}
render=build/bin/engine-render
engine_glb=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

run() {  # engine-render's report of one setting
  "$render" --out "$out/frame.png" --width 1280 --height 720 --frames "$frames" "$@"
}
median_ms() { sed -n 's/.*median frame \([0-9.]*\) ms.*/\1/p'; }
# The light's map time from --stats (shadow_maps: one entry per light, by name).
map_ms() {
  python3 -c 'import json, sys
for light in json.load(open(sys.argv[1]))["shadow_maps"]:
    if light["light"] == sys.argv[2]: print(light["map_ms"])' "$1" "$2"
}

row() {  # name, scene, light, then extra engine-render args
  local name=$1 scene=$2 light=$3; shift 3
  local none static orbit depth cam_none cam_static
  none=$(run --config content/engine-unshadowed.json --scene "$scene" "$@" | median_ms)
  static=$(run --config content/engine.json --scene "$scene" "$@" | median_ms)
  orbit=$(run --config content/engine.json --scene "$scene" "$@" --orbit-light "$light" --stats "$out/orbit.json" | median_ms)
  depth=$(map_ms "$out/orbit.json" "$light")
  cam_none=$(run --config content/engine-unshadowed.json --scene "$scene" "$@" --orbit-camera | median_ms)
  cam_static=$(run --config content/engine.json --scene "$scene" "$@" --orbit-camera | median_ms)
  awk -v n="$name" -v a="$none" -v b="$static" -v c="$orbit" -v d="$depth" -v e="$cam_none" -v f="$cam_static" 'BEGIN {
    printf "%-16s %8.1f %8.1f %8.1f %8.1f %8.3f %12.3f | %8.1f %8.1f %8.3f\n",
           n, a, b, c, d, b / a, c / (a + d), e, f, f / e }'
}

echo "median frame ms over $frames frames, 1280x720, llvmpipe ($(nproc) cores)"
echo "                 ---------------- still camera --------------------------- | -- orbiting camera --"
printf "%-16s %8s %8s %8s %8s %8s %12s | %8s %8s %8s\n" scene none static orbiting depth \
  static/none "orbit/(n+d)" none static static/none
row showcase content/scenes/showcase.gltf spot_light
row lamps content/scenes/lamps.gltf lamp_0
if [ -f "$engine_glb" ]; then
  row 2CylinderEngine "$engine_glb" key_light --key-light spot
else
  echo "2CylinderEngine.glb not found (apt-get install assimp-testmodels)"
fi
