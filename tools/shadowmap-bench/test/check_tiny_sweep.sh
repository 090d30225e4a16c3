#!/usr/bin/env bash
# Runs shadowmap-bench on the showcase with one setting at 64x48 and checks results.csv
# (the exact header, one row per light, numbers in range) and summary.md.
# Usage: check_tiny_sweep.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
source "$(dirname "$0")/results_columns.sh"
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf \
  --width 64 --height 48 --frames 1 --out "$out"

csv=$out/results.csv
check_results_header "$csv"
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 3 ]] || { echo "expected 3 rows (the showcase's lights), got $rows"; exit 1; }
# Every light's shadow passes ran and took time (a map nobody reads would be culled and
# time 0: the sweep must re-render maps and recompute shade each frame); acne, leak, error,
# error_noedge and the area figures are percentages in [0, 100]; all plain numbers; the area
# error is the sum of its parts (to the CSV's 1e-4 rounding, three roundings: 3e-4) and
# nonzero (a 64x48 view of the showcase has partly lit pixels on every light's shadow edge).
# Without the optional axes nothing of them is written: the showcase's lights have no size
# (light_size 0, no soft figures) and the axes' columns are empty.
awk -F, 'NR > 1 {
  for (i = 7; i <= 15; ++i) if ($i !~ /^[0-9]+(\.[0-9]+)?$/) { print "not a number: " $i " in " $0; bad = 1 }
  if ($1 != "showcase" || $3 != "standard" || $4 != 256 || $5 != "d24" || $6 != "pcf") { print "bad setting: " $0; bad = 1 }
  if (!($7 > 0 && $8 > 0)) { print "bad time (a pass that did not run?): " $0; bad = 1 }
  for (i = 9; i <= 15; ++i) if (!($i >= 0 && $i <= 100)) { print "error out of [0,100]: " $0; bad = 1 }
  d = $15 - $13 - $14; if (d > 3e-4 || d < -3e-4) { print "area error is not acne + leak: " $0; bad = 1 }
  if (!($15 > 0)) { print "area error 0 (area truth not computed?): " $0; bad = 1 }
  if ($16 != "" || $17 != "" || $18 != "") { print "a shimmer or near figure without --shimmer, --near: " $0; bad = 1 }
  if ($19 != 0) { print "a light size on the showcase without --light-radii: " $0; bad = 1 }
  for (i = 20; i <= 25; ++i) if ($i != "") { print "column " i " filled without its axis or a sized light: " $0; bad = 1 }
  # Every light has evaluated pixels, so a texel size on screen (mean, p95): positive numbers.
  for (i = 26; i <= 27; ++i) if ($i !~ /^[0-9]+(\.[0-9]+)?$/ || !($i > 0)) { print "texel m not a positive number: " $i " in " $0; bad = 1 }
  # projection, cascades, stable, bleed_reduction: empty without --projections, --cascades,
  # --stables, --bleed-reductions.
  for (i = 28; i <= 31; ++i) if ($i != "") { print "column " i " filled without its axis: " $0; bad = 1 }
  if (NF != 33) { print NF " fields, expected 33: " $0; bad = 1 }
  # frame_p99_ms, frame_max_ms: the tail of the frames frame_ms is the median of, so
  # median <= p99 <= max, all positive.
  for (i = 32; i <= 33; ++i) if ($i !~ /^[0-9]+(\.[0-9]+)?$/ || !($i > 0)) { print "frame tail not a positive number: " $i " in " $0; bad = 1 }
  if (!($32 >= $8 && $33 >= $32)) { print "frame times not median <= p99 <= max: " $0; bad = 1 }
} END { exit bad }' "$csv"
[[ -s $out/summary.md ]] || { echo "summary.md missing or empty"; exit 1; }
# It cites the metric definitions by a file the repository has.
grep -q 'docs/metrics.md' "$out/summary.md" && [[ -f $content/../docs/metrics.md ]] \
  || { echo "summary.md does not cite docs/metrics.md for its error metrics"; exit 1; }
[[ -s $out/time_vs_error.gp ]] || { echo "time_vs_error.gp missing or empty"; exit 1; }
echo "ok: $rows rows"

# --near with a distance beyond the whole view scores every evaluated pixel: the near
# figures equal the overall ones, column for column.
"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf \
  --width 64 --height 48 --frames 1 --near 1e6 --out "$out/near"
awk -F, 'NR > 1 && ($17 != $11 || $18 != $12) { print "near figures differ from the overall ones at 1e6: " $0; bad = 1 }
         END { exit bad }' "$out/near/results.csv"
echo "ok: --near 1e6 gives the overall figures"

# A scene without lights gets the key light engine-render and engine-view place (spot by
# default), and --ground their ground; the placement is printed.
cp "$content/scenes/showcase.gltf" "$content/scenes/showcase.bin" "$out/"
python3 "$(dirname "$0")/../../scripts/remove_lights.py" "$out/showcase.gltf" "$out/dark.gltf"
"$bench" --config "$content/engine.json" --scene "$out/dark.gltf" --ground \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf \
  --width 64 --height 48 --frames 1 --out "$out/dark" 2> "$out/dark.log"
grep -q 'shadowmap-bench: dark: key light: spot "key_light" at (' "$out/dark.log" \
  && grep -q 'shadowmap-bench: dark: ground: (' "$out/dark.log" \
  || { echo "no key light or ground placement printed: $(cat "$out/dark.log")"; exit 1; }
rows=$(tail -n +2 "$out/dark/results.csv" | wc -l)
[[ $rows -eq 1 ]] || { echo "expected 1 row (the key light), got $rows"; exit 1; }
echo "ok: a light-less scene swept with the key light and a ground"
