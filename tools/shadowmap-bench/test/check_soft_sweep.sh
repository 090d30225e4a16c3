#!/usr/bin/env bash
# shadowmap-bench's optional axes on the showcase (spot_light, sun, point_light) at 64x48:
# one light size step, wide pcf radii, tap counts and normal offsets. Checks which rows the
# axes make, that every sized light is scored against the soft truth, and that summary.md
# ranks sized lights by their soft error.
# Usage: check_soft_sweep.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf,pcss \
  --light-radii 0.1 --angular-diameters 0.05 --filter-radii 0,2 --filter-taps 8 --normal-offsets 0,0.5 \
  --width 64 --height 48 --frames 1 --out "$out" 2> "$out/log" || { cat "$out/log"; exit 1; }

csv=$out/results.csv
# Rows: one size step; pcf x filter radii 0 and 2, of which only radius 2 takes taps (x 1
# count): 2 pcf settings; pcss x 1 tap count (filter radii are pcf's): 1 setting; 3 settings
# x 2 normal offsets = 6 settings, x 3 lights = 18 rows.
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 18 ]] || { echo "expected 18 rows, got $rows"; cat "$out/log"; exit 1; }
# Columns 19-25: light_size, filter_radius, filter_taps, normal_offset, soft_error,
# soft_error_noedge, penumbra_error. Each light has the step's size (the sun its angular
# diameter); every row is scored against the soft truth, in [0, 100]; pcss rows have no
# filter radius and 8 taps, pcf rows radius 0 without taps or radius 2 with 8; each
# (light, filter, radius, taps, offset) once.
awk -F, 'NR > 1 {
  size = ($2 == "sun") ? 0.05 : 0.1
  if ($19 != size) { print "light_size " $19 ", expected " size ": " $0; bad = 1 }
  for (i = 23; i <= 25; ++i)
    if ($i !~ /^[0-9]+(\.[0-9]+)?$/ || !($i >= 0 && $i <= 100)) { print "soft figure " i " not in [0,100]: " $0; bad = 1 }
  if ($6 == "pcss" && !($20 == "" && $21 == 8)) { print "pcss row with a filter radius or without 8 taps: " $0; bad = 1 }
  if ($6 == "pcf" && !(($20 == 0 && $21 == "") || ($20 == 2 && $21 == 8))) { print "bad pcf radius/taps: " $0; bad = 1 }
  if ($6 != "pcf" && $6 != "pcss") { print "unexpected filter: " $0; bad = 1 }
  if ($22 != 0 && $22 != 0.5) { print "bad normal offset: " $0; bad = 1 }
  if (seen[$2 "," $6 "," $20 "," $21 "," $22]++) { print "row twice: " $0; bad = 1 }
} END { exit bad }' "$csv"
echo "ok: 18 rows, every sized light scored against the soft truth"

# The summary says what it ranks by, and ranks by it: each light's best setting at any time
# carries that light's lowest soft error (the CSV's 1e-4 rounding against the summary's 1e-3).
summary=$out/summary.md
grep -q 'a light with a size (light_size > 0) is ranked by its soft error' "$summary" \
  || { echo "summary.md does not say it ranks sized lights by soft error"; exit 1; }
for light in spot_light sun point_light; do
  best=$(grep "^| showcase | $light |" "$summary" | head -n 1 | sed -E 's/.*\(([0-9.]+) %\) \|$/\1/')
  lowest=$(awk -F, -v l="$light" 'NR > 1 && $2 == l && (min == "" || $23 < min) { min = $23 } END { print min }' "$csv")
  awk -v b="$best" -v m="$lowest" 'BEGIN { d = b - m; exit !(b != "" && d < 0.0011 && d > -0.0011) }' \
    || { echo "$light: best at any time $best %, lowest soft error $lowest %"; exit 1; }
done
echo "ok: summary.md ranks sized lights by soft error"
