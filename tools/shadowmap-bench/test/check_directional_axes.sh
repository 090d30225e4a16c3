#!/usr/bin/env bash
# shadowmap-bench's directional lights' axes (--projections, --cascades, --stables) on the
# showcase (spot_light, sun, point_light) at 64x48: which rows they make, the projection,
# cascades and stable columns, the labels; that a spot or point light is given none of the
# three keys and written once, not once per value; that pcss with lispsm is left out with one
# note; and that two shards merged equal the single run.
# Usage: check_directional_axes.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
source "$(dirname "$0")/results_columns.sh"
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

sweep() {
  "$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
    --variants standard --resolutions 256 --depth-formats d24 --filters pcf \
    --projections uniform,lispsm --cascades 1,auto --stables true,false \
    --width 64 --height 48 --frames 1 "$@"
}
sweep --out "$out/single" 2> "$out/log" || { cat "$out/log"; exit 1; }

csv=$out/single/results.csv
check_results_header "$csv"
# The sun: uniform x 2 cascade counts x 2 stables + lispsm x 2 cascade counts (stable is not
# swept for a warp) = 6 rows; the spot and point lights one row each: 8 rows.
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 8 ]] || { echo "expected 8 rows (6 sun, 1 spot, 1 point), got $rows"; cat "$csv"; exit 1; }
# Columns 28-30: projection, cascades, stable. The sun's rows: each combination once, lispsm
# rows without stable; the spot and point lights' rows: all three empty. Every row is
# measured (check_rows_measured).
check_rows_measured "$csv"
awk -F, 'NR > 1 {
  if ($2 == "sun") {
    if ($28 != "uniform" && $28 != "lispsm") { print "sun without a swept projection: " $0; bad = 1 }
    if ($29 != "1" && $29 != "auto") { print "sun without a swept cascade count: " $0; bad = 1 }
    if ($28 == "uniform" && $30 != "true" && $30 != "false") { print "uniform sun row without stable: " $0; bad = 1 }
    if ($28 == "lispsm" && $30 != "") { print "lispsm row with stable: " $0; bad = 1 }
    if (seen[$28 "," $29 "," $30]++) { print "sun row twice: " $0; bad = 1 }
    sun++
  } else {
    if ($28 != "" || $29 != "" || $30 != "") { print "a spot or point light row with a directional axis: " $0; bad = 1 }
    if (others[$2]++) { print "a spot or point light written twice: " $0; bad = 1 }
  }
} END { if (sun != 6) { print sun " sun rows, expected 6"; bad = 1 } exit bad }' "$csv"
# Labels (progress, summary) name what was set.
grep -q 'showcase sun standard 256 d24 pcf lispsm cauto:' "$out/log" \
  && grep -q 'showcase sun standard 256 d24 pcf uniform c1 unstable:' "$out/log" \
  && grep -q 'showcase spot_light standard 256 d24 pcf:' "$out/log" \
  || { echo "progress labels without the axes' tags:"; cat "$out/log"; exit 1; }
grep -q 'showcase / sun' "$out/single/summary.md" && grep -Eq 'pcf (uniform|lispsm) c(1|auto)' "$out/single/summary.md" \
  || { echo "summary.md labels without the axes' tags"; exit 1; }
# The progress counts the rows it writes: [8/8] last.
grep -q '^\[8/8\]' "$out/log" || { echo "progress does not count to the 8 rows written:"; cat "$out/log"; exit 1; }
echo "ok: 8 rows, the directional axes on the sun only"

# Shards: the sweep's 6 jobs dealt to 2 shards; a spot or point light's row comes from the
# first job of its group whichever shard runs it, so the merge equals the single run.
check_shards_merge_to "$csv" "$out" "$bench"
echo "ok: two shards merged equal the single run"

# pcss with lispsm: the sun refuses it (the plugin's message), so that job is left out with
# one note; pcf lispsm and pcss uniform stay. Sizes make pcss possible at all.
"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf,pcss \
  --light-radii 0.1 --angular-diameters 0.05 --projections uniform,lispsm \
  --width 64 --height 48 --frames 1 --out "$out/pcss" 2> "$out/pcss.log" || { cat "$out/pcss.log"; exit 1; }
notes=$(grep -c 'no filter' "$out/pcss.log" || true)
grep -q '^shadowmap-bench: showcase: no filter pcss rows at lr0.1 ad0.05 with projection lispsm: .*light "sun".projection: "lispsm"' \
  "$out/pcss.log" && [[ $notes -eq 1 ]] || { cat "$out/pcss.log"; echo "expected one note leaving pcss lispsm out, got $notes"; exit 1; }
# Jobs: pcf uniform, pcf lispsm, pcss uniform: the sun 3 rows, spot and point 2 each (pcf, pcss).
rows=$(tail -n +2 "$out/pcss/results.csv" | wc -l)
[[ $rows -eq 7 ]] || { echo "expected 7 rows, got $rows"; cat "$out/pcss/results.csv"; exit 1; }
awk -F, 'NR > 1 && $6 == "pcss" && $28 == "lispsm" { print "a pcss lispsm row: " $0; bad = 1 } END { exit bad }' \
  "$out/pcss/results.csv"
echo "ok: pcss with lispsm left out with one note"
