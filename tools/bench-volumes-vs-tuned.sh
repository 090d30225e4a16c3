#!/usr/bin/env bash
# Shadow volumes against the light's own map and the tuner's best map, in one run. Per light:
# (a) its own setting as variant standard, (b) the setting shadowmap-tune wrote into TUNED for
# it (--light-set per key, on the untuned scene, so the other lights stay as they were), (c)
# volume; alternating run by run, at 1280x720, with the light orbiting (its shadow redone every
# frame) and still (cache_maps false, so every frame draws every shadow). Figures as
# tools/bench-volumes.sh prints them; the error against ray-traced truth at 1280x720, the light
# where the scene puts it.
# Usage: tools/bench-volumes-vs-tuned.sh SCENE TUNED LIGHT[,LIGHT...] [engine-render args...]
#   e.g. build/bin/shadowmap-tune --scene S --budget-ms 1000 --variants standard,woo,backface
#        --out TUNED; then  tools/bench-volumes-vs-tuned.sh S TUNED spot_light,sun
#   env: BIN (default build/bin), FRAMES (default 20)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1 tuned=$2 lights=$3; shift 3
render=${BIN:-build/bin}/engine-render
frames=${FRAMES:-20}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# --light-set NAME.KEY=JSON for every key of the light's extras.shadow in the tuned .gltf/.glb.
tuned_args() {
  python3 -c 'import json, struct, sys
data = open(sys.argv[1], "rb").read()
if data[:4] == b"glTF":
    data = data[20:20 + struct.unpack("<I", data[12:16])[0]]
g = json.loads(data)
light = next(l for l in g["extensions"]["KHR_lights_punctual"]["lights"] if l.get("name") == sys.argv[2])
for k, v in light.get("extras", {}).get("shadow", {}).items():
    print("--light-set\n%s.%s=%s" % (sys.argv[2], k, json.dumps(v)))' "$tuned" "$1"
}
source tools/scripts/volume-bench-figures.sh

echo "$(basename "$scene"): $frames frames at 1280x720, llvmpipe ($(nproc) cores); error at 1280x720"
printf "%-12s %-6s %-8s %4s %s\n" light motion variant run "$FIGURES_HEADER $ERRORS_HEADER"
for light in ${lights//,/ }; do
  mapfile -t best < <(tuned_args "$light")
  declare -A args=([default]="--light $light=standard" [tuned]="" [volume]="--light $light=volume")
  for motion in orbit still; do
    if [ $motion = orbit ]; then how=(--orbit-light "$light"); else how=(--set shadowmap_plugin.cache_maps=false); fi
    for round in 1 2; do
      for variant in default tuned volume; do
        if [ $variant = tuned ]; then v=("${best[@]}"); else read -ra v <<< "${args[$variant]}"; fi
        "$render" --scene "$scene" "$@" "${v[@]}" --out "$out/frame.png" --width 1280 --height 720 \
          --frames "$frames" "${how[@]}" --stats "$out/$light-$motion-$variant-$round.json" > /dev/null
      done
    done
  done
  for variant in default tuned volume; do
    if [ $variant = tuned ]; then v=("${best[@]}"); else read -ra v <<< "${args[$variant]}"; fi
    "$render" --scene "$scene" "$@" "${v[@]}" --out "$out/frame.png" --width 1280 --height 720 \
      --truth --stats "$out/$light-$variant-truth.json" > /dev/null
  done
  echo "$light tuned: ${best[*]}"
  for motion in orbit still; do
    for variant in default tuned volume; do
      for round in 1 2; do
        printf "%-12s %-6s %-8s run%s %s %s\n" "$light" $motion $variant $round \
          "$(figures "$out/$light-$motion-$variant-$round.json" "$light")" "$(errors "$out/$light-$variant-truth.json" "$light")"
      done
    done
  done
done
