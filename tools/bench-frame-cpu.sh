#!/usr/bin/env bash
# Where a frame's CPU time goes on llvmpipe: the application thread (draw calls, vertex work,
# binning) and each of llvmpipe's rasterizer threads (fragment work), in ms of CPU per frame.
# On N cores no arrangement of the same work over contexts and threads can make a frame
# shorter than (sum of all threads) / N: docs/caching.md's "Where a moving frame's time goes"
# uses this to show what a speed target is up against.
# Method: perf samples per thread (cpu-clock, 1999 Hz) of two runs, FEW and MANY timed
# frames; the difference over MANY - FEW frames removes start-up, loading and warm-up.
# Usage: tools/bench-frame-cpu.sh [ENGINE-RENDER ARGS...]   (build first; needs perf:
#   apt-get install linux-perf)
# e.g. tools/bench-frame-cpu.sh --config content/engine.json --scene content/scenes/showcase.gltf --orbit-camera
set -euo pipefail
cd "$(dirname "$0")/.."
command -v perf >/dev/null || { echo "bench-frame-cpu: perf not found (apt-get install linux-perf)" >&2; exit 1; }
few=10 many=50
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
declare -A samples
for frames in $few $many; do
  perf record -q -F 1999 -o "$out/$frames.data" -- build/bin/engine-render --out "$out/frame.png" --width 1280 \
    --height 720 --frames "$frames" "$@" > "$out/$frames.txt"
  while read -r count thread; do samples[$frames.$thread]=$count; done < <(
    perf report -i "$out/$frames.data" --sort comm -g none --stdio -F sample,comm 2>/dev/null | grep -v '^#' | grep -v '^$')
done
head -1 "$out/$many.txt"
total=0
for key in "${!samples[@]}"; do
  [[ $key == $many.* ]] || continue
  thread=${key#"$many."}
  ms=$(awk -v a="${samples[$few.$thread]:-0}" -v b="${samples[$key]}" -v n=$((many - few)) \
         'BEGIN { printf "%.1f", (b - a) / 1999 / n * 1000 }')
  printf "  %-16s %6s ms of CPU per frame\n" "$thread" "$ms"
  total=$(awk -v t="$total" -v m="$ms" 'BEGIN { print t + m }')
done
printf "  %-16s %6s ms; on %d cores no frame of this work is shorter than %.1f ms\n" "all threads" "$total" \
  "$(nproc)" "$(awk -v t="$total" -v n="$(nproc)" 'BEGIN { print t / n }')"
