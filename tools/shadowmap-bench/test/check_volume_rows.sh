#!/usr/bin/env bash
# Variant volume (stenciled shadow volumes: no map, exact hard shadows) in a sweep of the
# showcase at 64x48: one row per light however many resolutions, formats, filters and map
# axes the sweep lists, its resolution, depth_format and filter columns and the map axes'
# columns empty, with a shadow time, a frame time and an error no map setting beats; its
# points in the time-vs-error plot under a shape and legend entry of their own; a light
# size step gives it a row per step; two shards merged equal the single run.
# Usage: check_volume_rows.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
source "$(dirname "$0")/results_columns.sh"
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

sweep() {
  "$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
    --variants standard,volume --resolutions 256,512 --depth-formats d24,d32f --filters nearest,pcf \
    --normal-offsets 0,0.25 --projections uniform,lispsm \
    --width 64 --height 48 --frames 1 "$@"
}
sweep --out "$out/single" 2> "$out/log" || { cat "$out/log"; exit 1; }
grep -q 'ignored' "$out/log" && { echo "the plugin ignored a setting the sweep gave volume: $(cat "$out/log")"; exit 1; }

csv=$out/single/results.csv
check_results_header "$csv"
# standard: 2 resolutions x 2 formats x 2 filters x 2 normal offsets = 16 settings, times 2
# projections on the sun (32 rows) and once on the spot and point lights (16 each); volume
# one row per light: 64 + 3 rows.
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 67 ]] || { echo "expected 67 rows (64 standard, 3 volume), got $rows"; cat "$csv"; exit 1; }
check_rows_measured "$csv"
awk -F, 'NR > 1 {
  if (!($8 > 0)) { print "no frame time: " $0; bad = 1 }
  if ($3 == "volume") {
    volume[$2]++
    if ($4 != "" || $5 != "" || $6 != "") { print "volume row with a map setting: " $0; bad = 1 }
    # filter_radius, filter_taps, normal_offset, the soft columns (no size here), no texel on
    # screen (no map), projection, cascades, stable, bleed_reduction: all empty.
    for (i = 20; i <= 31; ++i) if ($i != "") { print "volume row with column " i " set: " $0; bad = 1 }
    if (!($32 >= $8 && $33 >= $32)) { print "frame times not median <= p99 <= max: " $0; bad = 1 }
    # Exact at every pixel centre: away from the true shadow edges it errs on no pixel.
    if ($12 != 0) { print "volume row with an error off edges: " $0; bad = 1 }
    volumeError[$2] = $11
  } else {
    if ($4 == "" || $5 == "" || $6 == "") { print "map row without a map setting: " $0; bad = 1 }
    if (!($2 in bestMap) || $11 < bestMap[$2]) bestMap[$2] = $11
  }
} END {
  split("spot_light sun point_light", lights, " ")
  for (i = 1; i <= 3; ++i) {
    l = lights[i]
    if (volume[l] != 1) { print l ": " volume[l] + 0 " volume rows, expected 1"; bad = 1 }
    # Exact hard shadows: no map setting of the sweep errs less against the one-ray truth.
    # (The area truth, which the summary ranks by, counts the partly lit pixels of a hard edge
    # against it: there the soft 2x2 edge of pcf can score better, e.g. 0.46 % against 0.56 %
    # for the spot light of volume at 320x180.)
    if (!(volumeError[l] <= bestMap[l])) { print l ": volume error " volumeError[l] " above the best map " bestMap[l]; bad = 1 }
    printf "%s: volume error %s, best standard %s\n", l, volumeError[l], bestMap[l]
  }
  exit bad
}' "$csv"
# (Whether summary.md lists volume depends on the machine's timings -- its rows are the most
# accurate setting within a shadow-time budget and the time/error front -- so it is not checked
# here: under ASan on a fresh machine it listed none. The label is checked in the plot's data.)
# The plot draws volume's points in a shape of their own, larger, named in the legend.
plot=$out/single/time_vs_error.gp
grep -q '"volume" 1.8$' "$plot" || { echo "no volume point of size 1.8 in the plot's data"; exit 1; }
grep -q "NaN with points pt 15 ps 1.8 lc 'black' title 'volume (no map)'" "$plot" \
  || { echo "no volume entry in the plot's legend"; grep NaN "$plot"; exit 1; }
if command -v gnuplot > /dev/null; then
  (cd "$out/single" && gnuplot time_vs_error.gp) || { echo "gnuplot failed on the plot with volume points"; exit 1; }
fi
echo "ok: one volume row per light, empty map columns, plotted"

# A light size step is a row per step for volume too (its truth changes with the size).
"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" --variants volume \
  --light-radii 0,0.1 --angular-diameters 0,0.02 --width 64 --height 48 --frames 1 --out "$out/sized" 2> /dev/null
rows=$(tail -n +2 "$out/sized/results.csv" | wc -l)
[[ $rows -eq 6 ]] || { echo "sized: expected 6 volume rows (3 lights x 2 steps), got $rows"; exit 1; }

# Shards deal volume's job back like any other.
check_shards_merge_to "$out/single/results.csv" "$out" "$bench"
echo "ok: volume rows per size step; two shards merged equal the single run"
