#!/usr/bin/env bash
# shadowmap-bench's axes for the filterable maps on the showcase (spot_light, sun,
# point_light) at 64x48: --filter-radii multiplies the pcf, vsm and evsm rows (vsm, evsm: the
# moments' blur), --bleed-reductions the vsm and evsm rows only. Checks which rows they make,
# the filter_radius and bleed_reduction columns, the labels, that each key reaches the plugin
# (a bleed reduction only ever lowers a shade, so it cannot raise leak nor lower acne, and
# lowers leak somewhere; a blur changes some figure), and that two shards merged equal the
# single run (--merge reads the bleed_reduction column back).
# Usage: check_moments_axes.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
source "$(dirname "$0")/results_columns.sh"
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

sweep() {
  "$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
    --variants standard --resolutions 256 --depth-formats d24 --filters nearest,pcf,vsm,evsm \
    --filter-radii 0,2 --bleed-reductions 0,0.4 --width 64 --height 48 --frames 1 "$@"
}
sweep --out "$out/single" 2> "$out/log" || { cat "$out/log"; exit 1; }

csv=$out/single/results.csv
check_results_header "$csv"
# Settings: nearest 1 (no radius, no reduction); pcf x 2 radii; vsm and evsm x 2 radii x 2
# reductions each: 1 + 2 + 4 + 4 = 11, x 3 lights = 33 rows.
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 33 ]] || { echo "expected 33 rows, got $rows"; cat "$csv"; exit 1; }
# Columns: 6 filter, 9 acne, 10 leak, 20 filter_radius, 21 filter_taps, 31 bleed_reduction.
check_rows_measured "$csv"
awk -F, 'NR > 1 {
  if ($21 != "") { print "taps without --filter-taps: " $0; bad = 1 }
  if ($6 == "nearest" && ($20 != "" || $31 != "")) { print "nearest row with a radius or reduction: " $0; bad = 1 }
  if ($6 == "pcf" && (($20 != 0 && $20 != 2) || $31 != "")) { print "pcf row: radius 0 or 2, no reduction: " $0; bad = 1 }
  if (($6 == "vsm" || $6 == "evsm") && (($20 != 0 && $20 != 2) || ($31 != 0 && $31 != 0.4))) {
    print "vsm/evsm row without a swept radius and reduction: " $0; bad = 1
  }
  if (seen[$2 "," $6 "," $20 "," $31]++) { print "row twice: " $0; bad = 1 }
  key = $2 "," $6 "," $20
  if ($31 == "0") { leak0[key] = $10; acne0[key] = $9 }
  if ($31 == "0.4") { leak4[key] = $10; acne4[key] = $9 }
  if ($6 == "vsm" || $6 == "evsm") { blur[$2 "," $6 "," $31 "," $20] = $9 "," $10 "," $13 "," $14 }
} END {
  # The reduction maps a shade p to max(0, (p - r) / (1 - r)) <= p: leak never rises, acne
  # never falls (1e-4: the CSV rounding), and leak falls on some light (the key was applied).
  for (k in leak0) {
    if (!(k in leak4)) { print "no 0.4 row for " k; bad = 1; continue }
    if (leak4[k] > leak0[k] + 1e-4) { print k ": leak rose with bleed_reduction 0.4: " leak0[k] " -> " leak4[k]; bad = 1 }
    if (acne4[k] < acne0[k] - 1e-4) { print k ": acne fell with bleed_reduction 0.4: " acne0[k] " -> " acne4[k]; bad = 1 }
    if (leak4[k] < leak0[k] - 1e-4) lower++
  }
  if (lower == 0) { print "bleed_reduction 0.4 lowered no light'"'"'s leak: not applied?"; bad = 1 }
  # The blur: some vsm or evsm row measures differently at radius 2 than at 0.
  for (k in blur) if (k ~ /,0$/) { k2 = substr(k, 1, length(k) - 1) "2"; if (blur[k] != blur[k2]) changed++ }
  if (changed == 0) { print "filter_radius 2 changed no vsm or evsm figure: not applied?"; bad = 1 }
  exit bad
}' "$csv"
# Labels (progress, summary) name the radius and the reduction.
grep -q 'showcase spot_light standard 256 d24 vsm fr2 br0.4:' "$out/log" \
  && grep -q 'showcase sun standard 256 d24 evsm fr0 br0:' "$out/log" \
  && grep -q 'showcase point_light standard 256 d24 pcf fr2:' "$out/log" \
  && grep -q 'showcase sun standard 256 d24 nearest:' "$out/log" \
  || { echo "progress labels without fr/br:"; cat "$out/log"; exit 1; }
grep -Eq 'vsm fr[02] br0(\.4)?' "$out/single/summary.md" || { echo "summary.md labels without fr/br"; exit 1; }
grep -q '^\[33/33\]' "$out/log" || { echo "progress does not count to the 33 rows:"; cat "$out/log"; exit 1; }
echo "ok: 33 rows, filter radii on pcf, vsm and evsm, bleed reductions on vsm and evsm"

check_shards_merge_to "$csv" "$out" "$bench"
echo "ok: two shards merged equal the single run"
