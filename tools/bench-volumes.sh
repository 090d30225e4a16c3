#!/usr/bin/env bash
# Shadow volumes (variant volume) against the standard map (2048, pcf), in one run: the
# showcase's spot light, Debian's 2CylinderEngine.glb with its spot key light, and a torus
# of 10k to 1M triangles (tools/scripts/make_volume_scaling.py). Per scene and variant, with
# the light orbiting at 1280x720 (its shadow redone every frame), the variants alternating
# run by run: the median, p99 and max frame time, the light's shadow time (its map or volume
# passes; the first volume pass of a frame also draws the camera's depth), the silhouette
# edges, cap triangles and stencil fragments (fill) the volumes drew; then the error against ray-traced truth at
# 640x360 (percent of the light's evaluated pixels, and off truth's shadow edges).
# Usage: tools/bench-volumes.sh [FRAMES] [TRIANGLE COUNTS...]   (build first: tools/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-20}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10000 30000 100000 300000 1000000)
render=build/bin/engine-render
engine_glb=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source tools/scripts/volume-bench-figures.sh

row() {  # name, scene, light, then extra engine-render args
  local name=$1 scene=$2 light=$3; shift 3
  declare -A timed
  for round in 1 2; do  # alternating, so load on the machine falls on both
    for variant in standard volume; do
      "$render" --scene "$scene" "$@" --light "$light=$variant" --out "$out/frame.png" --width 1280 --height 720 \
        --frames "$frames" --orbit-light "$light" --stats "$out/$variant-$round.json" > /dev/null
    done
  done
  for variant in standard volume; do
    "$render" --scene "$scene" "$@" --light "$light=$variant" --out "$out/frame.png" --width 640 --height 360 \
      --truth --stats "$out/$variant-truth.json" > /dev/null
    for round in 1 2; do
      printf "%-22s %-9s %5s %s %s\n" "$name" "$variant" "run$round" "$(figures "$out/$variant-$round.json" "$light")" \
        "$(errors "$out/$variant-truth.json" "$light")"
    done
  done
}

echo "light orbiting, $frames frames at 1280x720; error at 640x360; llvmpipe ($(nproc) cores)"
printf "%-22s %-9s %5s %s\n" scene variant run "$FIGURES_HEADER $ERRORS_HEADER"
row showcase content/scenes/showcase.gltf spot_light
if [ -f "$engine_glb" ]; then
  row 2CylinderEngine "$engine_glb" key_light --key-light spot
else
  echo "2CylinderEngine.glb not found (apt-get install assimp-testmodels)"
fi
for triangles in "${sizes[@]}"; do
  python3 tools/scripts/make_volume_scaling.py "$out" "$triangles" > /dev/null
  row "torus $triangles" "$out/volume_scaling_$triangles.gltf" spot
done
