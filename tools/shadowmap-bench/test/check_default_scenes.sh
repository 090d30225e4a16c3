#!/usr/bin/env bash
# Runs shadowmap-bench's default scene list with one variant and one map size at 64x48 and
# checks which settings each scene got: the showcase every depth format and filter, the
# masked scenes and their opaque twins only d24 and pcf (BenchOptions.h, maskedScenes). The
# showcase's lights have no size, so pcss is left out there, with a note naming a light;
# vsm and evsm (the plugin's filterable maps) are in the default list and every showcase
# light takes them (finite far planes, no lispsm): 3 formats x 4 filters.
# Usage: check_default_scenes.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$bench" --config "$content/engine.json" --variants standard --resolutions 256 \
  --width 64 --height 48 --frames 1 --out "$out" 2> "$out/log" || { cat "$out/log"; exit 1; }
grep -q '^shadowmap-bench: showcase: no filter pcss rows: .*light "spot_light".filter: "pcss" softens the shadow' "$out/log" \
  || { cat "$out/log"; echo "no note that pcss is left out of the showcase"; exit 1; }

csv=$out/results.csv
awk -F, 'NR > 1 {
  rows[$1]++
  if ($1 ~ /^(masked|opaque)_(fence|canopy)$/ && ($5 != "d24" || $6 != "pcf")) { print "masked scene not at d24/pcf: " $0; bad = 1 }
  if ($1 == "showcase") { settings[$5 " " $6] = 1; filters[$6] = 1 }
} END {
  for (s in rows) printf "%s: %d rows\n", s, rows[s]
  n = 0; for (k in settings) n++
  if (n != 12) { print "showcase: expected 12 format/filter settings, got " n; bad = 1 }
  split("nearest pcf vsm evsm", listed, " ")
  for (i = 1; i <= 4; ++i) if (!(listed[i] in filters)) { print "showcase: no " listed[i] " rows"; bad = 1 }
  split("masked_fence opaque_fence masked_canopy opaque_canopy", masked, " ")
  for (i = 1; i <= 4; ++i) if (rows[masked[i]] != 3) { print masked[i] ": expected 3 rows (one per light), got " rows[masked[i]] + 0; bad = 1 }
  exit bad
}' "$csv"
echo ok
