#!/usr/bin/env bash
# The light-bleeding probe (tools/scripts/make_stacked_occluders.py: a grate high over a low
# slab, both lights low) measured by shadowmap-bench at 160x90: it shows what it is built to
# show. With no bleed reduction, vsm lets through at least twice pcf's leak at the same filter
# radius on each light (the blurred moments of two occluders at very different depths: light
# where every ray is blocked), evsm less than vsm (its exponential warp), and a reduction of
# 0.4 cuts both filters' leak below their unreduced leak.
# Usage: check_bleeding_probe.sh BENCH_BINARY CONTENT_DIR SCRIPTS_DIR
set -euo pipefail
bench=$1 content=$2 scripts=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

python3 "$scripts/make_stacked_occluders.py" "$out/scene"
"$bench" --config "$content/engine.json" --scene "$out/scene/stacked_occluders.gltf" \
  --variants standard --resolutions 512 --depth-formats d24 --filters pcf,vsm,evsm \
  --filter-radii 2 --bleed-reductions 0,0.4 --width 160 --height 90 --frames 1 \
  --out "$out/sweep" 2> "$out/log" || { cat "$out/log"; exit 1; }

# Columns: 2 light, 6 filter, 10 leak, 31 bleed_reduction. Both lights, 5 settings each.
awk -F, 'NR > 1 {
  rows++
  key = $2 "," $6 "," $31
  leak[key] = $10
  lights[$2] = 1
} END {
  if (rows != 10) { print rows " rows, expected 10 (sun and spot x pcf, vsm and evsm at 2 reductions)"; bad = 1 }
  if (!("sun" in lights) || !("spot" in lights)) { print "the probe lights are not sun and spot"; bad = 1 }
  for (l in lights) {
    pcf = leak[l ",pcf,"]; vsm = leak[l ",vsm,0"]; evsm = leak[l ",evsm,0"]
    printf "%s: leak %% pcf %s, vsm %s (0.4: %s), evsm %s (0.4: %s)\n", l, pcf, vsm, leak[l ",vsm,0.4"], evsm, leak[l ",evsm,0.4"]
    if (!(vsm > 2 * pcf)) { print l ": vsm does not bleed (leak " vsm " against pcf " pcf ")"; bad = 1 }
    if (!(evsm < vsm)) { print l ": evsm bleeds as much as vsm (" evsm " against " vsm ")"; bad = 1 }
    if (!(leak[l ",vsm,0.4"] < vsm && leak[l ",evsm,0.4"] < evsm)) { print l ": bleed_reduction 0.4 cut no leak"; bad = 1 }
  }
  exit bad
}' "$out/sweep/results.csv"
echo "ok: the probe bleeds with vsm, less with evsm, and the reduction cuts it"
