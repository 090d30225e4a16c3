#!/usr/bin/env bash
# A light size step of 0 on the showcase with pcf and pcss: pcss needs a size, so its rows
# are left out with one note for the step, however many normal offsets multiply them, and
# the pcf rows of unsized lights have no soft figures.
# Usage: check_unsized_soft_filter.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
  --variants standard --resolutions 256 --depth-formats d24 --filters pcf,pcss \
  --light-radii 0 --angular-diameters 0 --normal-offsets 0,0.5 \
  --width 64 --height 48 --frames 1 --out "$out" 2> "$out/log" || { cat "$out/log"; exit 1; }
notes=$(grep -c 'no filter' "$out/log" || true)
grep -q '^shadowmap-bench: showcase: no filter pcss rows at lr0 ad0: .*light "spot_light".filter: "pcss" softens the shadow' \
  "$out/log" && [[ $notes -eq 1 ]] || { cat "$out/log"; echo "expected one note leaving pcss out, got $notes"; exit 1; }

csv=$out/results.csv
rows=$(tail -n +2 "$csv" | wc -l)
[[ $rows -eq 6 ]] || { echo "expected 6 rows (pcf x 2 normal offsets x 3 lights), got $rows"; exit 1; }
awk -F, 'NR > 1 && ($6 != "pcf" || $19 != 0 || $23 != "" || $24 != "" || $25 != "") {
  print "not an unsized pcf row without soft figures: " $0; bad = 1
} END { exit bad }' "$csv"
echo "ok: pcss left out with one note, pcf rows without soft figures"
